// SPDX-License-Identifier: BSD-3-Clause
// What --resume does with a damaged FILE.partial: a torn row, a row with an extra or a missing field, `abc`
// in a number field are dropped and their points computed again (the table byte-identical to an uninterrupted
// sweep's), an exact repeat is accepted, and only two differing valid rows of one point are refused, naming
// the line. Also: a partial file of an earlier version, and one cut off in its first line.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "sweep/line_reader.hpp"
#include "sweep/sweep_partial.hpp"
#include "sweep/sweep_table.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::lines_of;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

constexpr std::size_t kPoints = 200;
const std::string kSweep =
    "sweep --zeta-range 0:10:200 --method taylor --tolerance 1e-2 --end naive --threads 2";
// The first line of that sweep's partial file.
const std::string kSettings =
    "# restitution sweep: zeta-min=0 zeta-max=10 points=200 spacing=linear end=naive method=taylor "
    "tolerance=0.01";

std::string line(std::size_t index, const std::string& row) {
  std::string text;
  append_partial_line(text, index, row);
  return text;
}

// The row with field `field` replaced (or removed when `by` is empty and `remove`).
std::string with_field(const std::string& row, std::size_t field, const std::string& by,
                       bool remove = false) {
  std::vector<std::string> fields(1);
  for (const char c : row) {
    if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back().push_back(c);
    }
  }
  if (remove) {
    fields.erase(fields.begin() + static_cast<std::ptrdiff_t>(field));
  } else {
    fields.at(field) = by;
  }
  std::string out = fields.front();
  for (std::size_t i = 1; i < fields.size(); ++i) out += "," + fields[i];
  return out;
}

class DamagedPartial : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto reference = run_cli(kSweep + " --out " + (dir_.path / "reference.csv").string());
    ASSERT_EQ(reference.status, 0) << reference.err;
    table_ = slurp(dir_.path / "reference.csv");
    rows_ = lines_of(table_);
    ASSERT_EQ(rows_.size(), kPoints + 1);
    preamble_ = kSettings + "\n" + partial_header(rows_[0]) + "\n";
  }
  [[nodiscard]] const std::string& row(std::size_t index) const { return rows_.at(index + 1); }

  TempFolder dir_;
  std::string table_, preamble_;
  std::vector<std::string> rows_;
};

TEST_F(DamagedPartial, DamagedRowsAreDroppedAndRecomputedAnExactRepeatAccepted) {
  const fs::path out = dir_.path / "s.csv";
  const fs::path partial = out.string() + ".partial";
  std::string text = preamble_;
  for (std::size_t i = 0; i < 100; ++i) {
    if (i == 10) {
      const std::string whole = line(10, row(10));
      text += whole.substr(0, whole.size() / 2);  // torn: the next line follows it (line 13)
    } else if (i == 11) {
      text += line(11, row(11));
    } else if (i == 20) {
      text += line(20, row(20) + ",7");  // an extra field, with a valid checksum
    } else if (i == 30) {
      text += line(30, with_field(row(30), 2, "", true));  // a missing field
    } else if (i == 40) {
      text += line(40, with_field(row(40), 1, "abc"));  // not a number
    } else {
      text += line(i, row(i));
    }
  }
  text += line(50, row(50));  // an exact repeat
  std::ofstream(partial, std::ios::binary) << text;

  // The reader: 95 points kept (not 10 and 11, torn; nor 20, 30 and 40), 4 lines dropped, one repeat.
  const PartialSweep read =
      parse_partial_sweep(text, partial, kSettings, rows_[0], zeta_values({0.0, 10.0, kPoints, false}));
  EXPECT_EQ(read.kept, 95U);
  EXPECT_EQ(read.dropped, 4U);
  EXPECT_EQ(read.first_dropped_line, 13U);
  EXPECT_EQ(read.duplicates, 1U);
  for (const std::size_t lost : {10U, 11U, 20U, 30U, 40U, 150U})
    EXPECT_EQ(read.row_offset.at(lost), PartialSweep::kNotDone) << lost;

  const auto resumed = run_cli(kSweep + " --resume --out " + out.string());
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(
      resumed.err.find(fmt::format("resuming: 95 of {} points already finished, computing {} (4 damaged "
                                   "lines of '{}' dropped, the first at line 13",
                                   kPoints, kPoints - 95, partial.string())),
      std::string::npos)
      << resumed.err;
  EXPECT_EQ(resumed.err.find("delete"), std::string::npos) << resumed.err;
  EXPECT_EQ(slurp(out), table_);
  EXPECT_FALSE(fs::exists(partial));
}

TEST_F(DamagedPartial, TwoDifferentValidRowsOfOnePointAreRefusedNamingTheLines) {
  const fs::path out = dir_.path / "s.csv";
  const fs::path partial = out.string() + ".partial";
  std::string text = preamble_;
  for (std::size_t i = 0; i < 8; ++i) text += line(i, row(i));
  text += line(5, with_field(row(5), 7, "99999"));  // line 11: point 5 again, another step count
  std::ofstream(partial, std::ios::binary) << text;
  const auto refused = run_cli(kSweep + " --resume --out " + out.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find(fmt::format("{}:11: point 5 ", partial.string())), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("at line 8"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("keep the one you trust"), std::string::npos) << refused.err;
  EXPECT_EQ(slurp(partial), text) << "the finished work stays as it was";
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(DamagedPartial, AFileCutOffInItsFirstLinesIsStartedAfresh) {
  const fs::path out = dir_.path / "s.csv";
  std::ofstream(out.string() + ".partial", std::ios::binary) << preamble_.substr(0, 30);
  const auto resumed = run_cli(kSweep + " --resume --out " + out.string());
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(fmt::format("resuming: 0 of {} points", kPoints)), std::string::npos)
      << resumed.err;
  EXPECT_EQ(slurp(out), table_);
}

TEST_F(DamagedPartial, AnEarlierVersionsFileIsNamedAsSuch) {
  const fs::path out = dir_.path / "s.csv";
  std::ofstream(out.string() + ".partial", std::ios::binary) << kSettings << "\n"
                                                             << rows_[0] << "\n0," << row(0) << "\n";
  const auto refused = run_cli(kSweep + " --resume --out " + out.string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("earlier version of restitution"), std::string::npos) << refused.err;
}

TEST(PartialLine, RoundTripsAndRefusesAnyChangedByte) {
  const std::string row = "0.5,0.57382462966163073,155,ok,";
  const std::string text = line(17, row);
  EXPECT_EQ(text.substr(0, 3 + row.size()), "17," + row);
  ASSERT_EQ(text.back(), '\n');
  const std::string whole = text.substr(0, text.size() - 1);
  ASSERT_TRUE(partial_line_row(whole));
  EXPECT_EQ(*partial_line_row(whole), row);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    std::string changed = whole;
    changed[i] = changed[i] == '1' ? '2' : '1';
    EXPECT_FALSE(partial_line_row(changed)) << changed;
  }
  EXPECT_FALSE(partial_line_row(whole.substr(0, whole.size() - 1)));
  EXPECT_FALSE(partial_line_row(""));
}

// A failed point's row keeps its axis columns (ζ, speed, β) and a quoted message with commas and quotes.
TEST(PartialLine, AFailedRowOfAVelocitySweepIsKeptAndCounted) {
  const std::vector<double> zetas{0.5, 1.0, 2.0};
  SweepColumns axis;
  axis.velocity_m_s = {0.1, 0.2, 0.3};
  axis.beta = 0.7;
  const std::string header = sweep_header(EndSet::both(), &axis);
  SweepPoint failed;
  failed.index = 1;
  failed.zeta = 1.0;
  failed.error = "CVODE failed, \"flag -1\", at tau=3";
  std::string text = "# s\n" + partial_header(header) + "\n";
  append_partial_line(text, 1, sweep_row(failed, EndSet::both(), &axis));
  const PartialSweep read = parse_partial_sweep(text, "p", "# s", header, zetas);
  EXPECT_EQ(read.kept, 1U);
  EXPECT_EQ(read.failed, 1U);
  EXPECT_EQ(read.dropped, 0U);
  // The same row with its speed emptied is not one the program writes.
  std::string damaged = "# s\n" + partial_header(header) + "\n";
  std::string row = sweep_row(failed, EndSet::both(), &axis);
  row.replace(row.find(",0.20000000000000001,"), 21, ",,");
  append_partial_line(damaged, 1, row);
  EXPECT_EQ(parse_partial_sweep(damaged, "p", "# s", header, zetas).dropped, 1U);
}

// A block of zeros without a line break (what a crash can leave in a file) is skipped, never held whole.
TEST(LineReader, AnOverlongLineIsHeldInPartAndSkippedWhole) {
  const std::size_t kLong = std::size_t{3} << 20;
  const std::string text = "a\n" + std::string(kLong, '\0') + "\nb\n" + std::string(kLong, '\0');
  LineReader lines = LineReader::of_text(text);
  EXPECT_EQ(lines.at(0).text, "a");
  const LineReader::Line zeros = lines.at(2);
  EXPECT_TRUE(zeros.complete);
  EXPECT_EQ(zeros.length, kLong);
  EXPECT_LE(zeros.text.size(), std::size_t{1} << 20);
  const LineReader::Line b = lines.at(2 + kLong + 1);
  EXPECT_EQ(b.text, "b");
  EXPECT_TRUE(b.complete);
  const LineReader::Line tail = lines.at(2 + kLong + 3);
  EXPECT_FALSE(tail.complete);
  EXPECT_EQ(tail.length, kLong);
  EXPECT_FALSE(lines.at(text.size()).complete);
}

}  // namespace
}  // namespace restitution
