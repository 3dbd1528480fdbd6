#include "util/language.hpp"

#include <algorithm>
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
  static const std::vector<Language> all = [] {
    std::vector<Language> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(data_dir() / "assets" / "locale", ec)) {
      if (entry.path().extension() != ".po") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      const std::string tag = entry.path().stem().string();
      std::string name = tag;
      try {
        const Catalog header = read_po(text.str(), entry.path().string());
        if (!header.name.empty()) name = header.name;
      } catch (const InputError&) {  // (listed: choosing it says what is wrong with it)
      }
      out.push_back({tag, name});
    }
    std::sort(out.begin(), out.end(),
              [](const Language& a, const Language& b) { return a.tag < b.tag; });
    out.insert(out.begin(), {"en", "English"});
    return out;
  }();
  return all;
}

std::string language_list() {
  std::string list;
  for (const Language& l : languages()) list += (list.empty() ? "" : ", ") + l.tag;
  return list;
}

namespace {

std::vector<std::string> spoken() {
  std::vector<std::string> tags;
  for (const Language& l : languages())
    if (l.tag != "en") tags.push_back(l.tag);
  return tags;
}

// Its translations use characters from U+2E80 on (CJK punctuation, ideographs, full-width
// forms), which DejaVu Sans lacks and the CJK font draws (ui/theme.cpp, by the same rule).
bool needs_cjk_font(const Catalog& catalog) {
  for (const auto& [english, translated] : catalog.entries)
    for (std::size_t i = 0; i < translated.size(); ++i) {
      const auto lead = static_cast<unsigned char>(translated[i]);
      // UTF-8: U+2E80 and above take three bytes or four, led by 0xE2 (with a second byte from
      // 0xBA) or anything from 0xE3.
      if (lead >= 0xE3 || (lead == 0xE2 && i + 1 < translated.size() &&
                           static_cast<unsigned char>(translated[i + 1]) >= 0xBA))
        return true;
    }
  return false;
}

}  // namespace

std::string use_language(const std::string& tag, bool draws) {
  std::string lang = supported_language(tag, spoken());
  if (lang == "en") {
    set_catalog(nullptr);
    return lang;
  }
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
  if (!in)
    throw InputError("language '" + lang + "': cannot read its translations, " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  Catalog catalog = read_po(text.str(), path.string());
  catalog.language = lang;
  if (draws && needs_cjk_font(catalog) && cjk_font_path().empty())
    throw InputError("language '" + lang +
                     "': its font is missing (the build makes it from Debian's fonts-noto-cjk "
                     "with python3-fonttools: scripts/setup.sh installs both)");
  loaded.push_back(std::move(catalog));
  set_catalog(&loaded.back());
  return lang;
}

std::string check_language(const std::string& tag, const std::string& what) {
  std::string lang = supported_language(tag, spoken());
  std::string lower;
  for (char c : tag) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lang == "en" &&
      !(lower == "en" || lower.rfind("en-", 0) == 0 || lower.rfind("en_", 0) == 0)) {
    throw InputError(what + ": '" + tag + "' is not a language springlab speaks (" +
                     language_list() + ")");
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
      std::string lang = supported_language(item, spoken());
      if (lang != "en" || item == "en" || item.rfind("en_", 0) == 0 || item.rfind("en-", 0) == 0)
        return lang;
    }
    return "en";  // (none it speaks: gettext then shows the messages untranslated)
  }
  return locale.empty() ? "en" : supported_language(locale, spoken());
}

std::string cjk_font_path() {
  std::error_code ec;
  if (const char* env = std::getenv("SPRINGLAB_CJK_FONT"); env && fs::is_regular_file(env, ec))
    return env;
#ifdef SPRINGLAB_CJK_FONT_BUILT
  if (fs::is_regular_file(SPRINGLAB_CJK_FONT_BUILT, ec)) return SPRINGLAB_CJK_FONT_BUILT;
#endif
  const fs::path shipped = data_dir() / "fonts" / "springlab-cjk.otf";
  if (fs::is_regular_file(shipped, ec)) return shipped.string();
  return "";
}

}  // namespace springlab::app
