// The words springlab shows, in its user's language, as gettext has it: every string is written in
// English in the code and passed through tr() where it is shown, which gives the current language's
// translation or, when there is none, the English (never an empty label). Translations are data:
// one gettext PO file a language (assets/locale/zh-CN.po), with the English text as the key, which
// translators' tools (Poedit, Lokalize, msgmerge) open. xgettext extracts the strings from the
// code (keywords tr and N_); the command line never sets a language and stays English.
// Placeholders are printf's (xgettext marks them c-format and msgfmt -c checks a translation keeps
// them), so numbers and units keep their format: "h = %.4g s".
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

// Marks a string for extraction where tr() cannot run (a constant table); tr() it where shown.
#define N_(english) english

namespace springlab {

// A language's translations: English -> translation. A key with a context is "context\x04english"
// (gettext's convention).
struct Catalog {
  // Looked up by any string type without making a std::string (C++20's heterogeneous lookup).
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::string language;  // "zh-CN": the header's Language
  std::string name;  // "简体中文": the header's X-Language-Name, the language's own name for itself
  std::unordered_map<std::string, std::string, Hash, std::equal_to<>> entries;
};

// Reads a PO file's text (`origin` names it in messages). Fuzzy and untranslated entries are left
// out (their English is shown). Throws InputError "origin:line: what is wrong" on a malformed file.
Catalog read_po(const std::string& text, const std::string& origin);

// The language tr() translates to: a catalog kept for the program's life (so the strings tr()
// returned stay valid when the language changes), or English (nullptr). Safe from any thread.
void set_catalog(const Catalog* catalog);
const Catalog* current_catalog();
// "zh-CN", or "en" with no catalog.
std::string current_language();

// `english` in the current language; `english` itself when it has no translation.
const char* tr(const char* english) __attribute__((format_arg(1)));
std::string tr(const std::string& english);

// printf into a string: format_text(tr("h = %.4g s"), h).
std::string format_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

// A language tag as the environment or a PO header gives it ("zh_CN.UTF-8", "pt_BR@euro") in the
// form springlab names its catalogs: "zh-CN", "pt-BR" (language lower case, region upper case,
// the encoding and modifier dropped).
std::string language_tag(const std::string& tag);

// A language tag as the environment gives it ("zh_CN.UTF-8", "zh-Hans-CN", "zh", "en-GB", "C") as
// one of the languages `spoken` (the catalogs' tags: "zh-CN", "fr") or "en": the same tag, else
// the first spoken one of the same language (Chinese in any region or script is the shipped
// Simplified Chinese; "fr-CA" is "fr"), else English.
std::string supported_language(const std::string& tag, const std::vector<std::string>& spoken);

}  // namespace springlab
