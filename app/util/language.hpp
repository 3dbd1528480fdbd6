// The language the app speaks (springlab/text.hpp): its catalogs are assets/locale/<tag>.po, read
// once and kept; chosen by --lang or the environment on the desktop, by the page's language or a
// link's lang= in the browser, and switched live from the View panel. The languages are the
// folder's files: a new one is its .po file (its header's X-Language-Name names it in the menu),
// and nothing else; a script beyond DejaVu Sans' (ideographs, from U+2E80 on) is drawn from the
// CJK font the build cuts to the catalogs' characters.
#pragma once

#include <string>
#include <vector>

namespace springlab::app {

struct Language {
  std::string tag;   // "zh-CN": the link's lang=, --lang, the catalog's file name
  std::string name;  // in its own language, for the menu: "简体中文"
};
// English first (no catalog: the code's own strings), then each catalog in assets/locale/, by tag.
const std::vector<Language>& languages();
// "en, zh-CN": the tags, for help and messages.
std::string language_list();

// Makes `tag` (any form the environment uses: "zh_CN.UTF-8", "zh-Hans", "en-GB") the language
// tr() translates to, loading its catalog the first time; returns the tag used ("zh-CN" or "en").
// A catalog that cannot be read or parsed throws InputError naming the file and line; so does
// one whose script needs the CJK font where it is missing, unless nothing is to be drawn
// (`draws` false: text on a terminal or in Python, which the terminal's own font shows).
std::string use_language(const std::string& tag, bool draws = true);

// A language named on the command line or in a link (`what`: "--lang"), as used: "en" or "zh-CN".
// Throws InputError for a language springlab has no translation for.
std::string check_language(const std::string& tag, const std::string& what);

// The desktop's language from the environment, as gettext reads it: LANGUAGE (the first entry
// springlab speaks, unless the locale is C), then LC_ALL, LC_MESSAGES, LANG; "en" when none is set.
std::string environment_language();

// The CJK font's file (the subset of Noto Sans CJK SC the build makes for the translations'
// characters), or "" where there is none: $SPRINGLAB_CJK_FONT, then the build tree's, then the
// data folder's fonts/.
std::string cjk_font_path();

}  // namespace springlab::app
