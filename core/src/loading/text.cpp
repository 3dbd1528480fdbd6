// gettext PO files (springlab/text.hpp), the small subset springlab's catalogs use and
// translators' tools write: comments and flags, msgctxt, msgid, msgid_plural, msgstr and
// msgstr[n] (the first form is kept), strings continued over several lines, C escapes.
#include "springlab/text.hpp"

#include <atomic>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <sstream>

#include "springlab/error.hpp"

namespace springlab {

namespace {

std::atomic<const Catalog*> g_catalog{nullptr};

struct Reader {
  const std::string& origin;
  int line = 0;
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(origin + ":" + std::to_string(line) + ": " + what);
  }
  // The string after a keyword: "..." with C escapes.
  std::string quoted(const std::string& text, std::size_t from) const {
    while (from < text.size() && std::isspace(static_cast<unsigned char>(text[from]))) ++from;
    if (from >= text.size() || text[from] != '"') fail("expected a quoted string");
    std::string out;
    std::size_t i = from + 1;
    for (; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] != '\\') {
        out += text[i];
        continue;
      }
      if (++i >= text.size()) fail("a backslash ends the line");
      switch (text[i]) {
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        default:
          fail(std::string("unknown escape \\") + text[i] + " (use \\n, \\t, \\\" or \\\\)");
      }
    }
    if (i >= text.size()) fail("a string is not closed (a \" is missing)");
    for (std::size_t j = i + 1; j < text.size(); ++j)
      if (!std::isspace(static_cast<unsigned char>(text[j]))) fail("text after the closing quote");
    return out;
  }
};

struct Entry {
  std::string context, id, str;
  bool has_context = false, has_id = false, has_str = false, fuzzy = false;
  int line = 0;
};

// The header's fields (the msgstr of the entry whose msgid is empty): "Language: zh_CN" sets the
// catalog's language, "X-Language-Name: ..." its name.
void po_read_header(Catalog& catalog, const std::string& header) {
  std::istringstream fields(header);
  const auto value = [](const std::string& field, std::size_t from) {
    const std::size_t start = field.find_first_not_of(' ', from);
    return start == std::string::npos ? std::string() : field.substr(start);
  };
  for (std::string field; std::getline(fields, field);) {
    if (field.rfind("Language:", 0) == 0) catalog.language = language_tag(value(field, 9));
    if (field.rfind("X-Language-Name:", 0) == 0) catalog.name = value(field, 16);
  }
}

// A whole entry into the catalog: it must have a msgid and a msgstr (else the reader fails at its
// first line); the header read as such; a fuzzy or untranslated one left out; a msgctxt's
// context kept before the msgid, joined by '\x04' as gettext keys it.
void po_add_entry(Catalog& catalog, Reader& reader, const Entry& entry) {
  if (!entry.has_id) {
    reader.line = entry.line;
    reader.fail("an entry has no msgid");
  }
  if (!entry.has_str) {
    reader.line = entry.line;
    reader.fail("msgid \"" + entry.id + "\" has no msgstr");
  }
  if (entry.id.empty()) {  // the header: "Language: zh_CN\n" among its fields
    po_read_header(catalog, entry.str);
  } else if (!entry.fuzzy && !entry.str.empty()) {
    catalog.entries[entry.has_context ? entry.context + '\x04' + entry.id : entry.id] = entry.str;
  }
}

}  // namespace

Catalog read_po(const std::string& text, const std::string& origin) {
  Catalog catalog;
  Reader reader{origin};
  Entry entry;
  std::string* target = nullptr;  // the string a continuation line extends
  std::string ignored;            // msgid_plural and msgstr[1...]: one form is kept
  const auto finish = [&] {
    if (entry.has_id || entry.has_context || entry.has_str) po_add_entry(catalog, reader, entry);
    entry = Entry{};
    target = nullptr;
  };
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    ++reader.line;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) {
      finish();
      continue;
    }
    if (line[start] == '#') {
      if (line.compare(start, 2, "#,") == 0 && line.find("fuzzy") != std::string::npos)
        entry.fuzzy = true;
      continue;
    }
    if (line[start] == '"') {
      if (!target) reader.fail("a continued string with no keyword before it");
      *target += reader.quoted(line, start);
      continue;
    }
    const std::size_t end = line.find_first_of(" \t\"", start);
    const std::string keyword = line.substr(start, end - start);
    if (!entry.has_id && !entry.has_context && !entry.has_str) entry.line = reader.line;
    // A keyword's string into `field`; a msgctxt or msgid after a whole entry's starts the next.
    const auto take = [&](std::string& field, bool& has, bool starts_new) {
      if (starts_new) {
        finish();
        entry.line = reader.line;
      }
      has = true;
      field = reader.quoted(line, end);
      target = &field;
    };
    if (keyword == "msgctxt") {
      take(entry.context, entry.has_context, entry.has_id || entry.has_context);
    } else if (keyword == "msgid") {
      take(entry.id, entry.has_id, entry.has_id);
    } else if (keyword == "msgstr" || keyword == "msgstr[0]") {
      take(entry.str, entry.has_str, false);
    } else if (keyword == "msgid_plural" || keyword.rfind("msgstr[", 0) == 0) {
      ignored = reader.quoted(line, end);
      target = &ignored;
    } else {
      reader.fail("unknown keyword '" + keyword +
                  "' (a PO file has msgctxt, msgid, msgid_plural and msgstr)");
    }
  }
  finish();
  return catalog;
}

void set_catalog(const Catalog* catalog) {
  g_catalog.store(catalog, std::memory_order_release);
}
const Catalog* current_catalog() {
  return g_catalog.load(std::memory_order_acquire);
}

std::string current_language() {
  const Catalog* c = current_catalog();
  return c && !c->language.empty() ? c->language : "en";
}

const char* tr(const char* english) {
  const Catalog* c = current_catalog();
  if (!c || !english || !*english) return english;
  const auto it =
      c->entries.find(std::string_view(english));  // (no string made: tr() runs every frame)
  return it == c->entries.end() ? english : it->second.c_str();
}

std::string tr(const std::string& english) {
  return tr(english.c_str());
}

std::string format_text(const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

std::string language_tag(const std::string& tag) {
  // Subtags by BCP 47's conventions: the language lower case, a script (four letters) title
  // case, a region (two letters) upper case.
  std::istringstream parts(tag.substr(0, tag.find_first_of(".@")));
  std::string out;
  for (std::string part; std::getline(parts, part, '-');) {
    for (std::size_t from = 0;;) {  // (an underscore separates as a hyphen does)
      const std::size_t to = part.find('_', from);
      std::string sub = part.substr(from, to == std::string::npos ? std::string::npos : to - from);
      for (std::size_t i = 0; i < sub.size(); ++i) {
        const auto c = static_cast<unsigned char>(sub[i]);
        const bool upper = !out.empty() && (sub.size() == 2 || (sub.size() == 4 && i == 0));
        sub[i] = static_cast<char>(upper ? std::toupper(c) : std::tolower(c));
      }
      out += (out.empty() ? "" : "-") + sub;
      if (to == std::string::npos) break;
      from = to + 1;
    }
  }
  return out;
}

std::string supported_language(const std::string& tag, const std::vector<std::string>& spoken) {
  const std::string wanted = language_tag(tag);
  const auto lower = [](std::string s) {
    for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return s;
  };
  const auto language = [&](const std::string& t) { return lower(t.substr(0, t.find('-'))); };
  for (const std::string& s : spoken)
    if (lower(s) == lower(wanted)) return s;
  for (const std::string& s : spoken)
    if (!wanted.empty() && language(s) == language(wanted)) return s;
  return "en";
}

}  // namespace springlab
