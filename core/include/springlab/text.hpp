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
  std::string language;  // "zh-CN"
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

// A language tag as the environment gives it ("zh_CN.UTF-8", "zh-Hans-CN", "zh", "en-GB", "C") as
// one springlab ships ("zh-CN") or "en": Chinese in any region or script is Simplified Chinese
// (the one translation), everything else English.
std::string supported_language(const std::string& tag);

}  // namespace springlab
