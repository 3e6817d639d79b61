// The contents of input files: the lines of a text file whatever its line ends and a UTF-8 byte
// order mark (UTF-16/32 refused, naming the bytes); SHA-256 against the FIPS 180-2 test vectors (one block, two
// blocks, a million bytes, empty input) and the run record's input files: an options file and
// a table an option names, each with the hash of its bytes, the paths apart from the hashes.
#include "io/options_files.hpp"
#include "io/run_record.hpp"
#include "io/sha256.hpp"
#include "io/text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace beamimpact;

// The same three lines (one of them empty) written with LF, CR LF, CR alone and mixed ends, with
// and without a UTF-8 byte order mark and a final line end: the same lines, no BOM or CR left.
TEST(TextLines, LineEndsAndByteOrderMark)
{
  const std::vector<std::string> want = {"-ball_speed 2", "", "# last"};
  for (const std::string bom : {"", "\xEF\xBB\xBF"})
    for (const std::string text : {"-ball_speed 2\n\n# last", "-ball_speed 2\r\n\r\n# last\r\n", "-ball_speed 2\r\r# last\r", "-ball_speed 2\r\n\r# last\n"}) {
      std::istringstream       in(bom + text);
      std::vector<std::string> lines;
      std::string              why;
      ASSERT_TRUE(TextLines(in, &lines, &why)) << why;
      EXPECT_EQ(want, lines) << "BOM " << bom.size() << " bytes, text '" << text << "'";
    }
  std::istringstream       empty("");
  std::vector<std::string> lines = {"stale"};
  std::string              why;
  EXPECT_TRUE(TextLines(empty, &lines, &why));
  EXPECT_TRUE(lines.empty());
}

// UTF-16 and UTF-32 (either byte order) are refused, naming the encoding and the first bytes.
TEST(TextLines, WideEncodingsRefused)
{
  const std::vector<std::pair<std::string, std::string>> cases = {{std::string("\xFF\xFE-\0b\0", 6), "UTF-16 text (it starts with the bytes FF FE)"},
                                                                  {std::string("\xFE\xFF\0-\0b", 6), "UTF-16 text (it starts with the bytes FE FF)"},
                                                                  {std::string("\xFF\xFE\0\0-\0\0\0", 8), "UTF-32 text (it starts with the bytes FF FE 00 00)"},
                                                                  {std::string("\0\0\xFE\xFF\0\0\0-", 8), "UTF-32 text (it starts with the bytes 00 00 FE FF)"}};
  for (const auto &c : cases) {
    std::istringstream       in(c.first);
    std::vector<std::string> lines;
    std::string              why;
    EXPECT_FALSE(TextLines(in, &lines, &why));
    EXPECT_NE(std::string::npos, why.find(c.second)) << why;
  }
}

TEST(Sha256, FipsVectors)
{
  EXPECT_EQ("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad", Sha256Hex("abc"));
  EXPECT_EQ("248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1", Sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"));
  EXPECT_EQ("cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0", Sha256Hex(std::string(1000000, 'a')));
  EXPECT_EQ("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855", Sha256Hex(""));
}

// The same bytes in pieces of any size: one digest (padding across block boundaries: 55, 56, 64 bytes).
TEST(Sha256, IncrementalEqualsWhole)
{
  for (size_t n : {55u, 56u, 63u, 64u, 65u, 1000u}) {
    std::string text;
    for (size_t i = 0; i < n; ++i) text += (char)('a' + i % 26);
    for (size_t piece : {1u, 7u, 64u}) {
      Sha256 s;
      for (size_t a = 0; a < n; a += piece) s.Update(text.data() + a, std::min(piece, n - a));
      EXPECT_EQ(Sha256Hex(text), s.HexDigest()) << n << " bytes in pieces of " << piece;
    }
  }
}

TEST(Sha256, FileAsItsBytes)
{
  char path[] = "/tmp/beamimpact-sha-XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(3, write(fd, "abc", 3));
  close(fd);
  std::string digest;
  EXPECT_TRUE(Sha256File(path, &digest));
  EXPECT_EQ(Sha256Hex("abc"), digest);
  unlink(path);
  EXPECT_FALSE(Sha256File(path, &digest));
  EXPECT_TRUE(digest.empty());
}

// An options file read and a table named by -ball_cor_table: both in the run's input files
// with the hashes of their bytes; the record holds the hashes by option, the paths apart.
TEST(RunRecordInputs, OptionsFileAndTableByContents)
{
  const std::string opts = "/tmp/beamimpact-inputs-test.opts", table = "/tmp/beamimpact-inputs-test.cor";
  std::ofstream(opts) << "-ball_speed 20\n";
  std::ofstream(table) << "# speed cor\n10 0.5\n30 0.4\n";
  std::vector<std::string> tokens;
  std::string              error;
  ASSERT_TRUE(OptionsFileExpand(opts, &tokens, &error)) << error;
  ASSERT_EQ(0, PetscOptionsSetValue(NULL, "-ball_cor_table", table.c_str()));
  std::vector<InputFile> files;
  ASSERT_EQ(0, RunInputFiles(&files));
  const std::vector<std::string> names = RunInputAttributeNames(files);
  bool saw_opts = false, saw_table = false;
  for (size_t k = 0; k < files.size(); ++k) {
    if (files[k].path == opts) {
      saw_opts = true;
      EXPECT_EQ("-options_file", files[k].option);
      EXPECT_EQ(Sha256Hex("-ball_speed 20\n"), files[k].sha256);
      EXPECT_EQ(0u, names[k].find("input_sha256_options_file"));
    }
    if (files[k].path == table) {
      saw_table = true;
      EXPECT_EQ("-ball_cor_table", files[k].option);
      EXPECT_EQ(Sha256Hex("# speed cor\n10 0.5\n30 0.4\n"), files[k].sha256);
      EXPECT_EQ("input_sha256_ball_cor_table", names[k]);
    }
  }
  EXPECT_TRUE(saw_opts);
  EXPECT_TRUE(saw_table);
  PetscOptionsClearValue(NULL, "-ball_cor_table");
  unlink(opts.c_str());
  unlink(table.c_str());
}

// Two files of one option are told apart: _2 for the second.
TEST(RunRecordInputs, AttributeNamesNumberRepeats)
{
  const std::vector<std::string> n = RunInputAttributeNames({{"-options_file", "a", ""}, {"-beam_profile", "p", ""}, {"-options_file", "b", ""}});
  ASSERT_EQ(3u, n.size());
  EXPECT_EQ("input_sha256_options_file", n[0]);
  EXPECT_EQ("input_sha256_beam_profile", n[1]);
  EXPECT_EQ("input_sha256_options_file_2", n[2]);
}
