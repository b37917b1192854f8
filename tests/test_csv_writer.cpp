// CSV as RFC 4180 writes it, and no cell a spreadsheet would run as a formula
// (core/io/csv_writer.h).
#include <gtest/gtest.h>

#include <string>

#include "core/io/csv_writer.h"

namespace {

using thinlayer::csv_text;
using thinlayer::CsvRow;

TEST(CsvWriter, PlainTextStaysAsItIs) {
  EXPECT_EQ(csv_text("bond_top"), "bond_top");
  EXPECT_EQ(csv_text("lap-joint-limit"), "lap-joint-limit");
  EXPECT_EQ(csv_text(""), "");
}

TEST(CsvWriter, AFieldHoldingACommaAQuoteOrANewlineIsQuoted) {
  EXPECT_EQ(csv_text("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_text("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(csv_text("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_text("cr\r"), "\"cr\r\"");
}

// OWASP's CSV injection: a cell beginning with = + - @ TAB CR is a formula to a spreadsheet.
TEST(CsvWriter, AFormulaIsNeutralisedAndQuotedWhereNeeded) {
  EXPECT_EQ(csv_text("=HYPERLINK(1),x"), "\"'=HYPERLINK(1),x\"");
  EXPECT_EQ(csv_text("=1+1"), "'=1+1");
  EXPECT_EQ(csv_text("+cmd"), "'+cmd");
  EXPECT_EQ(csv_text("-2+3"), "'-2+3");
  EXPECT_EQ(csv_text("@SUM(A1)"), "'@SUM(A1)");
  EXPECT_EQ(csv_text("\tx"), "'\tx");
  EXPECT_EQ(csv_text("\rx"), "\"'\rx\"");
}

TEST(CsvWriter, ARowJoinsItsFieldsNumbersStayNumbers) {
  const std::string line = CsvRow().text("=HYPERLINK(1),x").number(-1.5).integer(-3).text("limit").number(0.1, 3).line();
  EXPECT_EQ(line, "\"'=HYPERLINK(1),x\",-1.5,-3,limit,0.1\n");
  EXPECT_EQ(CsvRow().line(), "\n");
}

}  // namespace
