#include "core/markup.h"

#include <gtest/gtest.h>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

TEST(XmlEscaped, ReplacesTheFiveSpecialCharactersAndKeepsTheRest) {
  EXPECT_EQ(xmlEscaped("x<y & 'z' > \"w\""), "x&lt;y &amp; &#39;z&#39; &gt; &quot;w&quot;");
  EXPECT_EQ(xmlEscaped("\u2265 1.5 \u00b7 \u03c3\u2081"), "\u2265 1.5 \u00b7 \u03c3\u2081");  // UTF-8 passes through
  EXPECT_EQ(xmlEscaped("&amp;"), "&amp;amp;");  // escaped once more: the text is shown as written
  EXPECT_EQ(xmlEscaped(""), "");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
