// The command line people read: --help in sections with one style, the
// examples in each footer (they run), "did you mean" for mistyped commands
// and options, aliases, the two spellings of every switch, --version and
// the bash completion script.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "app/cli.hpp"
#include "app/option_style.hpp"
#include "app/options.hpp"
#include "cli/cli_run.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::out_path;
using testing::Result;
using testing::run;

const std::vector<std::string> kCommands = {"render", "view",   "compare",
                                            "bench",  "report", "completion"};

// Parses `line` (the arguments after "penumbra") as the tool does; returns
// the one-line error, or "" when it parses.
std::string parse_error(const std::string& line, CliArgs& args) {
  const std::unique_ptr<CLI::App> app = make_cli(args);
  try {
    app->parse(line, false);
  } catch (const CLI::ParseError& e) {
    return parse_error_message(*app, e);
  }
  return {};
}

std::string parse_error(const std::string& line) {
  CliArgs args;
  return parse_error(line, args);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The section each option of a --help text is listed in: "--blur" -> "Filter".
std::map<std::string, std::string> sections_of(const std::string& help) {
  std::map<std::string, std::string> sections;
  std::string section;
  const std::regex title("^([A-Z][A-Za-z ]*):$");
  const std::regex option("^  (-[a-z], )?(--[a-z0-9-]+)");
  for (const std::string& line : lines_of(help)) {
    std::smatch m;
    if (std::regex_match(line, m, title)) {
      section = m[1];
    } else if (std::regex_search(line, m, option)) {
      sections[m[2]] = section;
    }
  }
  return sections;
}

// The commands under "Examples:" in a --help text, without "penumbra ".
std::vector<std::string> examples_of(const std::string& help) {
  std::vector<std::string> commands;
  bool in_examples = false;
  for (const std::string& line : lines_of(help)) {
    if (line == "Examples:") in_examples = true;
    if (in_examples && line.rfind("  penumbra ", 0) == 0) commands.push_back(line.substr(11));
  }
  return commands;
}

// Each table parameter's group, and "Unset" ones listed by name.
template <class Table>
void collect_ungrouped(const Table& table, std::vector<std::string>& ungrouped) {
  for (const auto& p : table) {
    if (p.group == OptionGroup::Unset) ungrouped.emplace_back(p.name);
  }
}

TEST(Help, EveryTableParameterNamesItsSection) {
  std::vector<std::string> ungrouped;
  collect_ungrouped(kShadowFloatParams, ungrouped);
  collect_ungrouped(kShadowIntParams, ungrouped);
  collect_ungrouped(kAccumulateParams, ungrouped);
  collect_ungrouped(kRendererShadowIntParams, ungrouped);
  collect_ungrouped(kRendererShadowFloatParams, ungrouped);
  collect_ungrouped(kRendererShadowSwitchParams, ungrouped);
  collect_ungrouped(kSourceSizeParams, ungrouped);
  collect_ungrouped(kSsaoIntParams, ungrouped);
  collect_ungrouped(kSsaoFloatParams, ungrouped);
  collect_ungrouped(kShadowFlagParams, ungrouped);
  collect_ungrouped(kShadowSwitchParams, ungrouped);
  collect_ungrouped(kSsaoSwitchParams, ungrouped);
  collect_ungrouped(kRenderIntParams, ungrouped);
  collect_ungrouped(kReferenceIntParams, ungrouped);
  std::string names;
  for (const std::string& n : ungrouped) names += " --" + n;
  EXPECT_TRUE(ungrouped.empty()) << "parameters without an OptionGroup (shown in their table's "
                                    "section):"
                                 << names;
}

// Every option of every command is in one of the named sections: one
// registered without a group would land in "Other", beside --help.
TEST(Help, EveryOptionIsInANamedSection) {
  CliArgs args;
  const std::unique_ptr<CLI::App> app = make_cli(args);
  std::string ungrouped;
  for (const CLI::App* command : app->get_subcommands({})) {
    for (const CLI::Option* option : command->get_options()) {
      if (option == command->get_help_ptr() || option->get_group().empty()) continue;
      bool known = false;
      for (const auto& [group, title] : kOptionGroupNames) {
        known |= group != OptionGroup::Other && option->get_group() == title;
      }
      if (!known) ungrouped += " " + command->get_name() + " " + option->get_name();
    }
  }
  EXPECT_TRUE(ungrouped.empty()) << "options in no named section:" << ungrouped;
}

TEST(Help, RenderShowsItsSectionsInOrderWithTheirOptions) {
  const Result r = run("render --help");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> titles;
  for (const std::string& line : lines_of(r.out)) {
    if (!line.empty() && line.back() == ':' && line[0] != ' ') titles.push_back(line);
  }
  EXPECT_EQ(titles, (std::vector<std::string>{
                        "Output:", "Scene and camera:", "Lights:", "Technique:", "Filter:",
                        "Soft shadows:", "Bias:", "SSAO:", "Other:", "Examples:"}));
  const std::map<std::string, std::string> sections = sections_of(r.out);
  const std::map<std::string, std::string> expected = {{"--output", "Output"},
                                                       {"--view", "Output"},
                                                       {"--width", "Output"},
                                                       {"--scene", "Scene and camera"},
                                                       {"--camera-fov", "Scene and camera"},
                                                       {"--light", "Lights"},
                                                       {"--light-size", "Lights"},
                                                       {"--cascades", "Lights"},
                                                       {"--technique", "Technique"},
                                                       {"--pcf-samples", "Technique"},
                                                       {"--esm-c", "Technique"},
                                                       {"--filter", "Filter"},
                                                       {"--blur", "Filter"},
                                                       {"--soft", "Soft shadows"},
                                                       {"--accumulate", "Soft shadows"},
                                                       {"--constant-bias", "Bias"},
                                                       {"--normal-offset", "Bias"},
                                                       {"--ssao", "SSAO"},
                                                       {"--ssao-radius", "SSAO"},
                                                       {"--help", "Other"}};
  for (const auto& [option, section] : expected) {
    ASSERT_TRUE(sections.count(option)) << option << " missing from render --help";
    EXPECT_EQ(sections.at(option), section) << option;
  }
}

TEST(Help, CompareAndBenchHaveTheirOwnSections) {
  Result r = run("compare --help");
  ASSERT_EQ(r.status, 0) << r.err;
  std::map<std::string, std::string> sections = sections_of(r.out);
  EXPECT_EQ(sections["--reference-samples"], "Reference");
  EXPECT_EQ(sections["--cache"], "Reference");
  EXPECT_EQ(sections["--cache-dir"], "Reference");
  EXPECT_EQ(sections["--technique"], "Technique");
  r = run("bench --help");
  ASSERT_EQ(r.status, 0) << r.err;
  sections = sections_of(r.out);
  EXPECT_EQ(sections["--frames"], "Measurement");
  EXPECT_EQ(sections["--sweep"], "Measurement");
  EXPECT_EQ(sections["--json"], "Output");
}

// One style: a placeholder that says what the value is, choices and
// ranges in brackets with the default; nothing wider than 80 columns.
TEST(Help, OneStyleAndNoLongLines) {
  for (const std::string& command : kCommands) {
    const Result r = run(command + " --help");
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    for (const std::string& line : lines_of(r.out)) {
      EXPECT_LE(line.size(), 80u) << command << ": " << line;
      for (const char* bare : {" TEXT", " INT", " FLOAT", " UINT", "=hard", "REQUIRED"}) {
        EXPECT_EQ(line.find(bare), std::string::npos) << command << ": " << line;
      }
    }
  }
  // Descriptions are wrapped: read them as one line.
  const std::string help = std::regex_replace(run("render --help").out, std::regex("\n +"), " ");
  for (const char* shown :
       {"--blur N ", "--esm-c X ", "--technique NAME ", "--soft, --no-soft ", "--output FILE ",
        "--camera-position X,Y,Z ", "[range: 0 to 64; default: 2]",
        "[one of: gaussian, sat; default: gaussian]", "[default: off]"}) {
    EXPECT_NE(help.find(shown), std::string::npos) << shown;
  }
}

// The examples in every footer parse as the tool parses them; render's,
// compare's and bench's also run, at a tiny size.
TEST(Help, EveryCommandHasExamplesThatParse) {
  for (const std::string& command : kCommands) {
    const Result r = run(command + " --help");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<std::string> examples = examples_of(r.out);
    EXPECT_GE(examples.size(), 2u) << command;
    for (const std::string& example : examples) {
      EXPECT_TRUE(example.rfind(command + " ", 0) == 0 || example == command) << example;
      EXPECT_EQ(parse_error(example), "") << example;
    }
  }
}

TEST(Help, RenderCompareAndBenchExamplesRun) {
  const fs::path dir = fs::path(out_path("examples"));
  fs::create_directories(dir);
  // The examples name files of the source tree (scenes/...) and write
  // into the current folder.
  fs::create_directory_symlink(fs::path(PENUMBRA_SOURCE_DIR) / "scenes", dir / "scenes");
  const std::map<std::string, std::string> tiny = {
      {"render", " --width 32 --height 24 --shadow-map-size 128"},
      {"compare",
       " --width 32 --height 24 --shadow-map-size 128 --reference-samples 4 --cache-dir cache"},
      {"bench", " --width 32 --height 24 --shadow-map-size 128 --frames 1 --warmup 0"},
  };
  for (const auto& [command, small] : tiny) {
    const Result help = run(command + " --help");
    for (const std::string& example : examples_of(help.out)) {
      const std::string line = "cd " + dir.string() + " && " + PENUMBRA_BINARY + " " + example +
                               small + " > /dev/null 2> err.txt";
      EXPECT_EQ(std::system(line.c_str()), 0) << example << "\n"
                                              << std::ifstream(dir / "err.txt").rdbuf();
    }
  }
  EXPECT_TRUE(fs::exists(dir / "hard.png"));
  EXPECT_TRUE(fs::exists(dir / "compare" / "reference-traced.png"));
  EXPECT_TRUE(fs::exists(dir / "bench.json"));
}

TEST(Suggestions, AMistypedCommandIsNamedWithTheNearestOne) {
  const Result r = run("rendr");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "penumbra: error: unknown command 'rendr'; did you mean 'render'?\n");
  EXPECT_EQ(parse_error("comapre"), "unknown command 'comapre'; did you mean 'compare'?");
  EXPECT_NE(parse_error("frobnicate").find("unknown command 'frobnicate' (choose render, "),
            std::string::npos);
}

// The unknown option is named first, before a missing --output, with the
// nearest option of that command.
TEST(Suggestions, AMistypedOptionIsNamedFirst) {
  const std::string out = out_path("suggest.png");
  const Result r = run("render --techniqe pcf -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "penumbra: error: unknown option '--techniqe' for 'render'; did you mean "
            "'--technique'?\n");
  EXPECT_FALSE(fs::exists(out));
  const Result bogus = run("render --bogus");
  EXPECT_EQ(bogus.status, 2);
  EXPECT_TRUE(testing::is_one_error_line(bogus.err, "'--bogus'")) << bogus.err;
  EXPECT_EQ(bogus.err.find("--output"), std::string::npos) << bogus.err;
  EXPECT_EQ(parse_error("compare --blurr=3"),
            "unknown option '--blurr' for 'compare'; did you mean '--blur'?");
  EXPECT_EQ(parse_error("bench --sweeep blur"),
            "unknown option '--sweeep' for 'bench'; did you mean '--sweep'?");
  EXPECT_EQ(parse_error("render -o x.png stray"),
            "unexpected argument 'stray' (see 'penumbra render --help')");
  EXPECT_EQ(parse_error("render -o x.png --technique"), "--technique needs a value");
  EXPECT_EQ(parse_error("--technique pcf render -o x.png"),
            "unknown option '--technique' (options follow the command: penumbra render "
            "--technique ...)");
}

TEST(Suggestions, AMistypedNameIsNamedWithTheNearestOne) {
  EXPECT_NE(parse_error("render -o x.png --technique pfc").find("did you mean 'pcf'?"),
            std::string::npos);
  EXPECT_NE(parse_error("compare --technique hard,vsn").find("'vsn'"), std::string::npos);
  EXPECT_NE(parse_error("compare --technique hard,vsn").find("did you mean 'vsm'?"),
            std::string::npos);
  EXPECT_NE(parse_error("render -o x.png --view shadwo").find("did you mean 'shadow'?"),
            std::string::npos);
}

// The README and the report spell techniques "PCSS" and "MSM": names
// parse without regard to case wherever they are read, and a mistyped one
// in capitals gets its suggestion like any other.
TEST(Suggestions, NamesIgnoreCase) {
  for (const char* line :
       {"render -o x.png --technique PCSS", "render -o x.png --technique Msm16",
        "render -o x.png --filter SAT --view Shadow", "compare --technique HARD,Pcss,msm",
        "bench --techniques ALL", "view --technique EVSM4"}) {
    EXPECT_EQ(parse_error(line), "") << line;
  }
  EXPECT_EQ(parse_technique_list("HARD,Pcss,msm16", "--technique"),
            (std::vector<Technique>{Technique::Hard, Technique::Pcss, Technique::Msm16}));
  EXPECT_EQ(parse_technique_list("All", "--technique").size(), technique_names().size() - 1);
  EXPECT_EQ(parse_enum<Technique>(kTechniqueNames, "PcSs"), Technique::Pcss);
  EXPECT_EQ(parse_enum<Filter>(kFilterNames, "Gaussian"), Filter::Gaussian);
  EXPECT_EQ(parse_enum<Technique>(kTechniqueNames, "pcss "), std::nullopt);
  EXPECT_NE(parse_error("render -o x.png --technique PCSX").find("did you mean 'pcss'?"),
            std::string::npos);
  EXPECT_NE(parse_error("compare --technique HARD,VSMM").find("did you mean 'vsm'?"),
            std::string::npos);
}

// --technique takes one name in render and view, a list in compare and
// bench; compare and bench also read --techniques.
TEST(Aliases, TechniqueAndTechniquesAreOneOption) {
  for (const char* command : {"compare", "bench"}) {
    for (const char* flag : {"--technique", "--techniques"}) {
      CliArgs args;
      const std::string line = std::string(command) + " " + flag + " hard,msm16";
      ASSERT_EQ(parse_error(line, args), "") << line;
      const std::string& list =
          std::string(command) == "compare" ? args.compare.techniques : args.bench.techniques;
      EXPECT_EQ(list, "hard,msm16") << line;
    }
  }
  EXPECT_NE(parse_error("render -o x.png --technique hard,pcf").find("--technique"),
            std::string::npos);
}

// Every switch reads "--name", "--no-name", and the older "--name on|off"
// and "--name=false".
TEST(Booleans, EverySwitchHasBothSpellingsAndTheOldOnes) {
  const auto render = [](const std::string& flags) {
    CliArgs args;
    const std::string error = parse_error("render -o x.png " + flags, args);
    EXPECT_EQ(error, "") << flags;
    return args.render;
  };
  EXPECT_TRUE(render("--soft").shadow.soft);
  EXPECT_FALSE(render("--no-soft").shadow.soft);
  EXPECT_FALSE(render("--soft=false").shadow.soft);
  EXPECT_TRUE(render("--soft on").shadow.soft);
  EXPECT_FALSE(render("--no-guard-band").shadow.guard_band);
  EXPECT_FALSE(render("--guard-band off").shadow.guard_band);
  EXPECT_TRUE(render("--guard-band").shadow.guard_band);
  EXPECT_FALSE(render("").shadow.contact_shadows);
  EXPECT_TRUE(render("--contact-shadows").shadow.contact_shadows);
  EXPECT_FALSE(render("--contact-shadows off").shadow.contact_shadows);
  EXPECT_FALSE(render("--no-ssao").ssao.enabled);
  EXPECT_FALSE(render("--ssao off").ssao.enabled);
  EXPECT_TRUE(render("--ssao").ssao.enabled);
  EXPECT_TRUE(render("--ssao-half-resolution").ssao.half_resolution);
  EXPECT_TRUE(render("--ssao-half-resolution on").ssao.half_resolution);
  EXPECT_TRUE(render("--soft-two-moment-blockers").shadow.soft_two_moment_blockers);
  CliArgs args;
  ASSERT_EQ(parse_error("compare --no-cache", args), "");
  EXPECT_FALSE(args.compare.cache);
  ASSERT_EQ(parse_error("compare --cache off", args = {}), "");
  EXPECT_FALSE(args.compare.cache);
  ASSERT_EQ(parse_error("compare", args = {}), "");
  EXPECT_TRUE(args.compare.cache);
  EXPECT_EQ(parse_error("render -o x.png --ssao --no-ssao"),
            "--no-ssao: contradicts --ssao (give one of them)");
  EXPECT_NE(parse_error("render -o x.png --soft maybe").find("--soft"), std::string::npos);
}

TEST(Version, PrintsTheProjectVersion) {
  const Result r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("penumbra ") + PENUMBRA_PROJECT_VERSION + "\n");
}

// Runs bash completion for the words typed so far (the last one is the
// word being completed) and returns the candidates, one per line.
std::string complete(const std::string& words) {
  const std::string script = out_path("complete-" + std::to_string(getpid()) + ".sh");
  {
    std::ofstream(script) << "source '" << PENUMBRA_COMPLETION_SCRIPT << "'\n"
                          << "COMP_WORDS=(" << words << ")\n"
                          << "COMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n"
                          << "_penumbra\n"
                          << "printf '%s\\n' \"${COMPREPLY[@]}\"\n";
  }
  FILE* pipe = popen(("bash " + script).c_str(), "r");
  std::string out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  fs::remove(script);
  return out;
}

TEST(Completion, TheInstalledScriptIsTheToolsOwn) {
  std::ifstream in(PENUMBRA_COMPLETION_SCRIPT);
  ASSERT_TRUE(in) << PENUMBRA_COMPLETION_SCRIPT;
  std::stringstream installed;
  installed << in.rdbuf();
  const Result r = run("completion");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, installed.str());
  EXPECT_EQ(std::system((std::string("bash -n ") + PENUMBRA_COMPLETION_SCRIPT).c_str()), 0);
}

TEST(Completion, CompletesCommandsOptionsAndNames) {
  EXPECT_EQ(complete("penumbra re"), "render\nreport\n");
  EXPECT_EQ(complete("penumbra render --techn"), "--technique\n");
  EXPECT_EQ(complete("penumbra compare --techn"), "--technique\n--techniques\n");
  EXPECT_EQ(complete("penumbra render --technique msm"), "msm\nmsm16\n");
  EXPECT_EQ(complete("penumbra compare --technique hard,v"), "hard,vsm\n");
  EXPECT_EQ(complete("penumbra render --no-ss"), "--no-ssao\n--no-ssao-half-resolution\n");
  EXPECT_EQ(complete("penumbra bench --sweep m"), "map-size\nmsaa\n");
  EXPECT_EQ(complete("penumbra view --scene sp"), "spot\n");  // and files beginning "sp"
  EXPECT_EQ(complete("penumbra render --blur ''"), "\n");     // a number: nothing to offer
}

// Every option of every command, and every name each option takes, is in
// the script: it is written from the same registration.
TEST(Completion, KnowsEveryOptionAndName) {
  std::ifstream in(PENUMBRA_COMPLETION_SCRIPT);
  std::stringstream text;
  text << in.rdbuf();
  const std::string script = text.str();
  CliArgs args;
  const std::unique_ptr<CLI::App> app = make_cli(args);
  for (const CLI::App* command : app->get_subcommands({})) {
    for (const CLI::Option* option : command->get_options()) {
      for (const std::string& name : option->get_lnames()) {
        EXPECT_NE(script.find(" --" + name), std::string::npos)
            << command->get_name() << " " << name;
      }
      for (const std::string& choice : option_choices(*option)) {
        EXPECT_NE(script.find(choice), std::string::npos) << option->get_name() << " " << choice;
      }
    }
  }
  for (const auto& [technique, name] : kTechniqueNames) {
    EXPECT_EQ(complete("penumbra render --technique " + std::string(name)).find(name), 0u) << name;
  }
}

}  // namespace
}  // namespace penumbra
