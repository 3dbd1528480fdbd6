#include "util/language.hpp"

#include <cctype>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

const std::vector<Language>& languages() {
  static const std::vector<Language> all = {{"en", "English"}, {"zh-CN", "\u7b80\u4f53\u4e2d\u6587"}};
  return all;
}

std::string use_language(const std::string& tag) {
  const std::string lang = supported_language(tag);
  if (lang == "en") {
    set_catalog(nullptr);
    return lang;
  }
  if (cjk_font_path().empty())
    throw InputError("language '" + lang + "': its font is missing (the build makes it from Debian's fonts-noto-cjk "
                     "with python3-fonttools: scripts/setup.sh installs both)");
  // Every catalog read stays for the program's life: strings tr() gave out point into it.
  static std::mutex mutex;
  static std::deque<Catalog> loaded;
  const std::lock_guard lock(mutex);
  for (const Catalog& c : loaded)
    if (c.language == lang) {
      set_catalog(&c);
      return lang;
    }
  const fs::path path = data_dir() / "assets" / "locale" / (lang + ".po");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("language '" + lang + "': cannot read its translations, " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  Catalog catalog = read_po(text.str(), path.string());
  catalog.language = lang;
  loaded.push_back(std::move(catalog));
  set_catalog(&loaded.back());
  return lang;
}

std::string check_language(const std::string& tag, const std::string& what) {
  const std::string lang = supported_language(tag);
  std::string lower;
  for (char c : tag) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lang == "en" && !(lower == "en" || lower.rfind("en-", 0) == 0 || lower.rfind("en_", 0) == 0)) {
    std::string known;
    for (const Language& l : languages()) known += (known.empty() ? "" : ", ") + std::string(l.tag);
    throw InputError(what + ": '" + tag + "' is not a language springlab speaks (" + known + ")");
  }
  return lang;
}

std::string environment_language() {
  const auto get = [](const char* name) -> std::string {
    const char* value = std::getenv(name);
    return value ? value : "";
  };
  // The locale's messages: the first of LC_ALL, LC_MESSAGES, LANG that is set.
  std::string locale = get("LC_ALL");
  if (locale.empty()) locale = get("LC_MESSAGES");
  if (locale.empty()) locale = get("LANG");
  // LANGUAGE, a list in order of preference ("fr:zh_CN:en"), comes first, except under the C
  // locale (as GNU gettext does): its first language springlab speaks, English included.
  const std::string list = get("LANGUAGE");
  if (!list.empty() && locale != "C" && locale != "POSIX") {
    std::istringstream items(list);
    for (std::string item; std::getline(items, item, ':');) {
      const std::string lang = supported_language(item);
      if (lang != "en" || item == "en" || item.rfind("en_", 0) == 0 || item.rfind("en-", 0) == 0) return lang;
    }
    return "en";  // (none it speaks: gettext then shows the messages untranslated)
  }
  return locale.empty() ? "en" : supported_language(locale);
}

std::string cjk_font_path() {
  std::error_code ec;
  if (const char* env = std::getenv("SPRINGLAB_CJK_FONT"); env && fs::is_regular_file(env, ec)) return env;
#ifdef SPRINGLAB_CJK_FONT_BUILT
  if (fs::is_regular_file(SPRINGLAB_CJK_FONT_BUILT, ec)) return SPRINGLAB_CJK_FONT_BUILT;
#endif
  const fs::path shipped = data_dir() / "fonts" / "springlab-cjk.otf";
  if (fs::is_regular_file(shipped, ec)) return shipped.string();
  return "";
}

}  // namespace springlab::app
