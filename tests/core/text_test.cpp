// Translations as data (springlab/text.hpp): the PO reader against gettext's format, tr()'s
// fallback to English, and the language tags the environment and browsers give.
#include "springlab/text.hpp"

#include <gtest/gtest.h>

#include "springlab/error.hpp"

namespace springlab::test {
namespace {

TEST(Text, ReadsWhatGettextWrites) {
  const Catalog c = read_po(R"(# a comment
msgid ""
msgstr ""
"Language: zh_CN\n"
"Content-Type: text/plain; charset=UTF-8\n"

#: app/ui/panels.cpp:12
#, c-format
msgid "t = %.3f s"
msgstr "t = %.3f 秒"

msgid "a long message "
"over two lines"
msgstr ""
"一条"
"长消息"

msgctxt "button"
msgid "Open"
msgstr "打开"

#, fuzzy
msgid "unsure"
msgstr "不确定"

msgid "untranslated"
msgstr ""

msgid "quote \" and\nnewline"
msgstr "引号 \" 和\n换行"

msgid "one file"
msgid_plural "%d files"
msgstr[0] "%d 个文件"
)",
                            "test.po");
  EXPECT_EQ(c.language, "zh-CN");
  EXPECT_EQ(c.entries.at("t = %.3f s"), "t = %.3f 秒");
  EXPECT_EQ(c.entries.at("a long message over two lines"), "一条长消息");
  EXPECT_EQ(c.entries.at(std::string("button") + '\x04' + "Open"), "打开");
  EXPECT_EQ(c.entries.at("quote \" and\nnewline"), "引号 \" 和\n换行");
  EXPECT_EQ(c.entries.at("one file"), "%d 个文件");
  EXPECT_EQ(c.entries.count("unsure"), 0u);        // fuzzy: not trusted, the English shows
  EXPECT_EQ(c.entries.count("untranslated"), 0u);  // never an empty label
  EXPECT_EQ(c.entries.count(""), 0u);              // the header is not a message
}

TEST(Text, AMalformedCatalogIsOneMessageWithItsLine) {
  const auto error = [](const std::string& text) {
    try {
      read_po(text, "zh-CN.po");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("msgid \"a\"\nmsgstr \"b"),
            "zh-CN.po:2: a string is not closed (a \" is missing)");
  EXPECT_EQ(error("msgid \"a\"\n\nmsgstr \"b\""), "zh-CN.po:1: msgid \"a\" has no msgstr");
  EXPECT_EQ(error("msgid \"a\"\nmsgstr \"\\q\""),
            "zh-CN.po:2: unknown escape \\q (use \\n, \\t, \\\" or \\\\)");
  EXPECT_EQ(error("msgid \"a\"\nmsgtxt \"b\""),
            "zh-CN.po:2: unknown keyword 'msgtxt' (a PO file has msgctxt, msgid, msgid_plural and "
            "msgstr)");
  EXPECT_EQ(error("\"orphan\""), "zh-CN.po:1: a continued string with no keyword before it");
}

TEST(Text, TranslatesWhatTheCatalogHasAndLeavesTheRestInEnglish) {
  static const Catalog c =
      read_po("msgid \"Energy\"\nmsgstr \"能量\"\n\nmsgid \"Language: x\"\nmsgstr \"\"\n", "t.po");
  EXPECT_STREQ(tr("Energy"), "Energy");  // no catalog: English
  EXPECT_EQ(current_language(), "en");
  set_catalog(&c);
  EXPECT_STREQ(tr("Energy"), "能量");
  EXPECT_EQ(tr(std::string("Energy")), "能量");
  EXPECT_STREQ(tr("Phase"), "Phase");  // missing: the English, never empty
  EXPECT_STREQ(tr(""), "");
  set_catalog(nullptr);
  EXPECT_STREQ(tr("Energy"), "Energy");
  EXPECT_EQ(format_text(tr("h = %.4g s, %d steps"), 0.0083333, 12), "h = 0.008333 s, 12 steps");
}

TEST(Text, ChineseInAnyFormIsSimplifiedChineseAndTheRestEnglish) {
  const std::vector<std::string> shipped{"zh-CN"};
  for (const char* tag :
       {"zh_CN.UTF-8", "zh-CN", "zh", "zh-Hans-CN", "ZH_cn", "zh_SG", "zh-TW", "zh.GB18030"})
    EXPECT_EQ(supported_language(tag, shipped), "zh-CN") << tag;
  for (const char* tag : {"en_US.UTF-8", "en-GB", "C", "POSIX", "", "fr_FR", "zhx"})
    EXPECT_EQ(supported_language(tag, shipped), "en") << tag;
}

// A second catalog is found by its tag: the exact region first, then any of its language.
TEST(Text, ALanguageIsMatchedByItsRegionThenByItsLanguage) {
  const std::vector<std::string> spoken{"pt-BR", "pt-PT", "zh-CN", "fr"};
  EXPECT_EQ(supported_language("pt_PT.UTF-8", spoken), "pt-PT");
  EXPECT_EQ(supported_language("pt_BR", spoken), "pt-BR");
  EXPECT_EQ(supported_language("pt", spoken), "pt-BR");
  EXPECT_EQ(supported_language("fr_CA.UTF-8@euro", spoken), "fr");
  EXPECT_EQ(supported_language("de_DE", spoken), "en");
  EXPECT_EQ(language_tag("zh_CN.UTF-8"), "zh-CN");
  EXPECT_EQ(language_tag("pt_br@euro"), "pt-BR");
  EXPECT_EQ(language_tag("zh-hans-cn"), "zh-Hans-CN");
  EXPECT_EQ(language_tag("fr"), "fr");
}

}  // namespace
}  // namespace springlab::test
