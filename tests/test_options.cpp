// Options files (includes and file paths relative to the including file, comments, quotes,
// cycles) and the closest-option suggestion for a misspelt name.
#include "base/options_util.hpp"
#include "io/options_files.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace beamimpact;

namespace {

std::string Scratch()
{
  char tmpl[] = "/tmp/beamimpact-options-XXXXXX";
  EXPECT_NE(nullptr, mkdtemp(tmpl));
  return tmpl;
}

void Write(const std::string &path, const std::string &text)
{
  std::ofstream(path) << text;
}

} // namespace

TEST(OptionsFiles, IncludesAndPathsRelativeToTheirFile)
{
  const std::string d = Scratch();
  ASSERT_EQ(0, system(("mkdir -p " + d + "/scenes " + d + "/bats").c_str()));
  Write(d + "/scenes/s.opts", "# a scene\n-options_file ../bats/b.opts   # the bat\n-sweep \"ball_speed=1:2:3, impact_x=0.5\"\n-impact_x 0.25\r\n-ts_dt -1e-3\n");
  Write(d + "/bats/b.opts", "-beam_profile b.profile\n-convergence_configs x.opts,/abs/y.opts,../z.opts\n");
  std::vector<std::string> t;
  std::string              err;
  ASSERT_TRUE(OptionsFileExpand(d + "/scenes/s.opts", &t, &err)) << err;
  const std::vector<std::string> want = {"-beam_profile", d + "/bats/b.profile", "-convergence_configs", d + "/bats/x.opts,/abs/y.opts," + d + "/z.opts", "-sweep", "ball_speed=1:2:3, impact_x=0.5", "-impact_x", "0.25", "-ts_dt", "-1e-3"};
  EXPECT_EQ(want, t);

  // On the command line a path stays relative to the working directory; other arguments are kept.
  std::vector<std::string> args;
  ASSERT_TRUE(OptionsArgsExpand({"-task", "impact", "-options_file", d + "/bats/b.opts", "-beam_profile", "here.profile"}, &args, &err)) << err;
  EXPECT_EQ(8u, args.size());
  EXPECT_EQ("here.profile", args.back());
}

TEST(OptionsFiles, MissingIncludeAndCycleNameTheFiles)
{
  const std::string d = Scratch();
  Write(d + "/a.opts", "-options_file missing.opts\n");
  std::vector<std::string> t;
  std::string              err;
  EXPECT_FALSE(OptionsFileExpand(d + "/a.opts", &t, &err));
  EXPECT_NE(std::string::npos, err.find("-options_file " + d + "/missing.opts (included by " + d + "/a.opts:1): cannot open the file")) << err;
  Write(d + "/loop.opts", "-beam_nodes 5\n-options_file loop.opts\n");
  err.clear();
  EXPECT_FALSE(OptionsFileExpand(d + "/loop.opts", &t, &err));
  EXPECT_NE(std::string::npos, err.find("includes nested deeper than")) << err;
}

// PETSc reads one option per line: a stray word or a second value is refused with file:line,
// not dropped (the command-line parser would skip it without a word).
TEST(OptionsFiles, StrayWordsAreRefused)
{
  const std::string d = Scratch();
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"-beam_nodes 21\n-impact_x 0.3 0.4\n", ":2: -impact_x has more than one value ('0.3', '0.4')"},
    {"# x\nimpact_x 0.3\n", ":2: 'impact_x' is not an option (an option starts with '-': -impact_x?)"},
    {"-options_file\n", ":1: -options_file needs a file name"},
  };
  for (auto &c : cases) {
    Write(d + "/bad.opts", c.first);
    std::vector<std::string> t;
    std::string              err;
    EXPECT_FALSE(OptionsFileExpand(d + "/bad.opts", &t, &err)) << c.first;
    EXPECT_NE(std::string::npos, err.find(d + "/bad.opts" + c.second)) << err;
  }
  std::vector<std::string> args;
  std::string              err;
  EXPECT_FALSE(OptionsArgsExpand({"-task", "impact", "-options_file"}, &args, &err));
  EXPECT_EQ("-options_file needs a file name", err);
  EXPECT_FALSE(OptionsArgsExpand({"-options_file", "-output", "x.h5"}, &args, &err));
}

TEST(OptionsClosest, SuggestsOnlyNearNames)
{
  const std::vector<std::string> known = {"-beam_length", "-beam_nodes", "-ball_speed", "-ball_k", "-impact_x", "-sweep_x"};
  EXPECT_EQ("-beam_length", OptionsClosest("-beam_lenght", known)); // a swap
  EXPECT_EQ("-beam_nodes", OptionsClosest("-beam_node", known));    // a deletion
  EXPECT_EQ("-impact_x", OptionsClosest("-impactx", known));        // an insertion
  EXPECT_EQ("-ball_speed", OptionsClosest("-ball_spede", known));
  EXPECT_EQ("", OptionsClosest("-no_such_thing", known));
  EXPECT_EQ("", OptionsClosest("-beam_width", known)); // 4+ edits from anything
}
