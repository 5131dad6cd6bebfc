// SPDX-License-Identifier: BSD-3-Clause
// `restitution fit-data` and scenes' [[fit]] on the input a user has, run as typed: extreme sigma, devices,
// FIFOs and files outside a scene, outputs that would replace the input or follow a dangling link, laws that
// are not candidates, residual tests that could not run, numbers at the ends of a double, hex floats, CR line
// ends, and the usual spellings of the columns.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

const std::string kRows = "0.5,0.8,0.01\n1,0.78,0.01\n2,0.75,0.01\n4,0.71,0.01\n";

std::string write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

nlohmann::json fit_json(const std::string& path) {
  const auto r = run_cli("fit-data " + path + " --json");
  EXPECT_EQ(r.status, 0) << path << ": " << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

// The first line of stderr: one line, exit 2, nothing on stdout.
std::string refusal(const std::string& arguments) {
  const auto r = run_cli(arguments);
  EXPECT_EQ(r.status, 2) << arguments << "\n" << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  return r.err;
}

std::string scene_with_data(const fs::path& folder, const std::string& data) {
  return write(folder / "scene.toml",
               "title = \"t\"\noutput = \"out\"\n[[fit]]\nname = \"drops\"\ndata = \"" + data + "\"\n");
}

// Item 4: every sigma the fit takes gives finite numbers; beyond the bounds it is refused in words.
TEST(FitDataInput, ExtremeSigmaIsFittedOrRefusedInWords) {
  const TempFolder t;
  for (const char* sigma : {"1e-100", "1e100", "1e-16", "3"}) {
    std::string rows;
    for (const char* row : {"0.5,0.8,", "1,0.78,", "2,0.75,"}) rows += std::string(row) + sigma + "\n";
    const auto j = fit_json(write(t.path / "s.csv", "v,eps,sigma\n" + rows));
    ASSERT_TRUE(j.contains("fits")) << sigma;
    for (const auto& f : j["fits"]) {
      EXPECT_TRUE(std::isfinite(f["chi2"].get<double>())) << sigma;
      EXPECT_TRUE(std::isfinite(f["aic"].get<double>())) << sigma;
    }
  }
  for (const char* sigma : {"1e-155", "1e-300", "1e155", "1e300"}) {
    const auto path =
        write(t.path / "s.csv", std::string("v,eps,sigma\n0.5,0.8,") + sigma + "\n1,0.7," + sigma + "\n");
    const std::string err = refusal("fit-data " + path);
    EXPECT_NE(err.find(":2:9: column 'sigma': must be in [1e-100, 1e+100]"), std::string::npos) << err;
    EXPECT_EQ(err.find("Random variate"), std::string::npos) << err;
  }
  // A scene's inline sigma goes through the same check.
  const auto scene = write(t.path / "inline.toml",
                           "title = \"t\"\noutput = \"out\"\n[[fit]]\nname = \"d\"\nv = [0.5, 1.0]\n"
                           "eps = [0.8, 0.7]\nsigma = [1e-155, 1e-155]\n");
  const std::string err = refusal("run " + scene + " --out " + (t.path / "o").string());
  EXPECT_NE(err.find("sigma must be in [1e-100, 1e+100]"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(t.path / "o"));
}

// Item 5: devices and endless streams stop at the documented bounds, fast.
TEST(FitDataInput, DevZeroAndAnEndlessFifoStopAtTheBounds) {
  const auto start = std::chrono::steady_clock::now();
  const std::string err = refusal("fit-data /dev/zero");
  EXPECT_NE(err.find("/dev/zero:1: the line is longer than 4096 bytes"), std::string::npos) << err;
  const TempFolder t;
  const fs::path fifo = t.path / "endless.csv";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // A writer that never stops: the reader stops it at the row bound (yes dies of SIGPIPE).
  const std::string writer = "(echo v,eps; exec yes 0.5,0.5) > " + fifo.string() + " 2>/dev/null &";
  ASSERT_EQ(std::system(writer.c_str()), 0);
  const std::string endless = refusal("fit-data " + fifo.string());
  EXPECT_NE(endless.find("more than 1000000 measurements, the bound of a fit CSV"), std::string::npos)
      << endless;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
}

// Item 5: a scene reads a regular file relative to itself, never a device, a FIFO or an absolute path.
TEST(FitDataInput, SceneDataIsARegularFileRelativeToTheScene) {
  const TempFolder t;
  for (const char* data : {"/dev/zero", "/etc/passwd", "/proc/self/environ"}) {
    const std::string err = refusal("run " + scene_with_data(t.path, data));
    EXPECT_NE(err.find("is absolute: a scene's data is a file relative to the scene file"), std::string::npos)
        << err;
    EXPECT_EQ(err.find("root:"), std::string::npos) << err;
  }
  ASSERT_EQ(mkfifo((t.path / "pipe.csv").c_str(), 0600), 0);
  const std::string err = refusal("run " + scene_with_data(t.path, "pipe.csv"));
  EXPECT_NE(err.find("not a regular file"), std::string::npos) << err;
  // A device or /proc through a link leads outside the scene's folder (SceneDataStaysInTheScenesFolder).
  fs::create_symlink("/dev/zero", t.path / "zero.csv");
  fs::create_symlink("/proc/self/environ", t.path / "environ.csv");
  for (const char* data : {"zero.csv", "environ.csv"}) {
    const std::string outside = refusal("run " + scene_with_data(t.path, data));
    EXPECT_NE(outside.find("leads outside the scene's folder"), std::string::npos) << data << ": " << outside;
  }
  EXPECT_FALSE(fs::exists(t.path / "out"));
  // The shipped scene reads data/ below itself from any working directory.
  const auto r = run_cli("run " + std::string(RESTITUTION_SOURCE_DIR) + "/scenes/ice_fit.toml --out " +
                         (t.path / "ice").string());
  EXPECT_EQ(r.status, 0) << r.err;
}

// Issue 45, item 7: a scene's data is read from within the scene's folder only, after symlinks; `..` is
// refused; nothing of a refused file is opened, so nothing of it is echoed.
TEST(FitDataInput, SceneDataStaysInTheScenesFolder) {
  const TempFolder t;
  fs::create_directories(t.path / "a" / "b");
  const std::string climbing =
      refusal("run " + scene_with_data(t.path / "a" / "b", "../../../../etc/shadow"));
  EXPECT_NE(climbing.find("climbs out with '..'"), std::string::npos) << climbing;
  fs::create_symlink("/etc/passwd", t.path / "passwd.csv");
  fs::create_symlink("/etc", t.path / "etc");  // a linked folder, then a file in it
  for (const char* data : {"passwd.csv", "etc/passwd"}) {
    const std::string err = refusal("run " + scene_with_data(t.path, data));
    EXPECT_NE(err.find("leads outside the scene's folder"), std::string::npos) << data << ": " << err;
    EXPECT_EQ(err.find("root:"), std::string::npos) << err;
  }
  // Below the scene's folder, through a link that stays inside, it is read.
  fs::create_directories(t.path / "measured");
  write(t.path / "measured" / "drops.csv", "v,eps\n0.5,0.8\n1,0.78\n2,0.75\n4,0.71\n");
  fs::create_directory_symlink(t.path / "measured", t.path / "latest");
  for (const char* data : {"measured/drops.csv", "latest/drops.csv"}) {
    const auto r = run_cli("run " + scene_with_data(t.path, data) + " --out " + (t.path / "out").string());
    EXPECT_EQ(r.status, 0) << data << ": " << r.err;
  }
}

// `restitution run SCENE --quick` from the folder `work`; its exit status, stdout and stderr.
test_support::CliOutcome run_scene_from(const fs::path& work, const std::string& scene) {
  return run_cli("--version >/dev/null && cd '" + work.string() + "' && " + RESTITUTION_EXE + " run " +
                 scene + " --quick");
}

// Issue 45, item 7: a scene's own `output` stays under the working folder after symlinks; a name holding an
// escape character is printed escaped.
TEST(FitDataInput, SceneOutputStaysUnderTheWorkingFolder) {
  const TempFolder t;
  const TempFolder elsewhere;
  fs::create_directory_symlink(elsewhere.path, t.path / "out");
  write(t.path / "scene.toml",
        "title = \"t\"\noutput = \"out/x\"\n[[trajectory]]\nname = \"tr\"\nzeta = 1\n");
  const auto r = run_scene_from(t.path, "scene.toml");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("leads outside the working folder"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(elsewhere.path)) << "written through the link";
  write(t.path / "escape.toml",
        "title = \"t\"\noutput = \"o\\u001b[2Jx\"\n[[trajectory]]\nname = \"tr\"\nzeta = 1\n");
  const auto escaped = run_scene_from(t.path, "escape.toml");
  EXPECT_EQ(escaped.status, 0) << escaped.err;
  EXPECT_EQ(escaped.out.find('\x1b'), std::string::npos) << "printed raw";
  EXPECT_NE(escaped.out.find("wrote o\\x1b[2Jx/"), std::string::npos) << escaped.out;
}

// Item 5: an error names file, line and column and echoes at most 40 characters, escaped.
TEST(FitDataInput, ErrorsEchoAShortEscapedExcerpt) {
  const TempFolder t;
  const std::string field = std::string("secret\x01\x1b[31m") + std::string(200, 'x');
  const auto path = write(t.path / "long.csv", "v,eps\n1,0.5\n2," + field + "\n");
  const std::string err = refusal("fit-data " + path);
  EXPECT_NE(
      err.find("long.csv:3:3: column 'eps': 'secret\\x01\\x1b[31mxxxxxxxxxxxxxxxxxxxxxxxxxxxx...' is not"),
      std::string::npos)
      << err;
  EXPECT_EQ(err.find('\x1b'), std::string::npos);
  EXPECT_LT(err.size(), 200U) << err;
}

// Item 6: the output never replaces an input, never creates folders through a link, is never empty.
TEST(FitDataInput, OutputNeverReplacesTheInputNorFollowsADanglingLink) {
  const TempFolder t;
  const std::string text = "v,eps,sigma\n" + kRows;
  const auto csv = write(t.path / "m.csv", text);
  std::string err = refusal("fit-data " + csv + " --out " + csv);
  EXPECT_NE(err.find("is the input"), std::string::npos) << err;
  fs::create_symlink(t.path / "m.csv", t.path / "link.json");
  err = refusal("fit-data " + csv + " --out " + (t.path / "link.json").string());
  EXPECT_NE(err.find("is the input"), std::string::npos) << err;
  EXPECT_EQ(slurp(csv), text);
  // A dangling link into folders that do not exist: refused, none of them created.
  fs::create_symlink(t.path / "elsewhere" / "deep" / "fit.json", t.path / "dangling.json");
  err = refusal("fit-data " + csv + " --out " + (t.path / "dangling.json").string());
  EXPECT_NE(err.find("whose folder does not exist"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(t.path / "elsewhere"));
  // --out and --plot one file: the figure would replace the report.
  err = refusal("fit-data " + csv + " --out " + (t.path / "f.png").string() + " --plot " +
                (t.path / "f.png").string());
  EXPECT_NE(err.find("--out '" + (t.path / "f.png").string() + "' and --plot"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(t.path / "f.png"));
  err = refusal("fit-data " + csv + " --out ''");
  EXPECT_NE(err.find("empty path"), std::string::npos) << err;
  // A dangling link into a folder that exists is written through, as before.
  fs::create_symlink(t.path / "fit.json", t.path / "ok.json");
  EXPECT_EQ(run_cli("fit-data " + csv + " --out " + (t.path / "ok.json").string()).status, 0);
  EXPECT_TRUE(fs::is_regular_file(t.path / "fit.json"));
}

// Item 7: a law that is not a candidate is refused naming the candidates; untested residuals say n/a.
TEST(FitDataInput, NonCandidateLawsAndUntestedResiduals) {
  const TempFolder t;
  const auto csv = write(t.path / "m.csv", "v,eps,sigma\n" + kRows);
  for (const char* law : {"hertz-constant-damping", "viscoelastic-hertz --law hertz-constant-damping"}) {
    const std::string err = refusal("fit-data " + csv + " --law " + law);
    EXPECT_NE(
        err.find("not a fit candidate: fit-data fits viscoelastic-hertz, tsuji-hertz and linear-dashpot"),
        std::string::npos)
        << err;
  }
  const auto two = write(t.path / "two.csv", "v,eps\n0.5,0.8\n1,0.75\n");
  const auto r = run_cli("fit-data " + two);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("n/a (too few points)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("  none\n"), std::string::npos) << r.out;
  const auto j = fit_json(two);
  for (const auto& f : j["fits"]) {
    EXPECT_FALSE(f["residual_tests"]["available"].get<bool>());
    EXPECT_EQ(f["residual_tests"]["verdict"], "n/a");
    EXPECT_EQ(f["residual_tests"]["unavailable"], "too few points");
  }
  const auto one_speed = fit_json(write(t.path / "same.csv", "v,eps\n1,0.8\n1,0.75\n1,0.77\n"));
  EXPECT_EQ(one_speed["fits"][0]["residual_tests"]["unavailable"], "one speed");
}

// Item 8: a subnormal literal is a number; one that underflows to 0 or overflows is refused in words.
TEST(FitDataInput, NumbersAtTheEndsOfADouble) {
  const TempFolder t;
  const auto j = fit_json(write(t.path / "sub.csv", "v,eps\n5e-324,0.5\n1,0.6\n"));
  EXPECT_EQ(j["data"]["v"][0].get<double>(), 5e-324);
  std::string err = refusal("fit-data " + write(t.path / "under.csv", "v,eps\n1,0.5\n2,1e-400\n"));
  EXPECT_NE(err.find(":3:3: column 'eps': '1e-400' is below the range of a double"), std::string::npos)
      << err;
  err = refusal("fit-data " + write(t.path / "over.csv", "v,eps\n1e400,0.5\n2,0.4\n"));
  EXPECT_NE(err.find(":2:1: column 'v': '1e400' is beyond the range of a double"), std::string::npos) << err;
  // 0 written with an exponent is a zero, not an underflow: refused as a speed, not as a number.
  err = refusal("fit-data " + write(t.path / "zero.csv", "v,eps\n0e-999,0.5\n2,0.4\n"));
  EXPECT_NE(err.find("the speed must be > 0 m/s"), std::string::npos) << err;
}

// Item 9: decimal numbers only; CR, LF and CRLF line ends; the speed-independent edge in the docs' words.
TEST(FitDataInput, HexFloatsLineEndsAndTheSpeedIndependentEdge) {
  const TempFolder t;
  for (const char* number : {"0x1p0", "0x0.8p0", "inf", "nan", "1e", ".", "1.5.2", "--1", "1 2"}) {
    const std::string err =
        refusal("fit-data " + write(t.path / "hex.csv", std::string("v,eps\n1,0.5\n") + number + ",0.4\n"));
    EXPECT_NE(err.find(":3:1: column 'v': '"), std::string::npos) << number << ": " << err;
    EXPECT_NE(err.find("is not a decimal number"), std::string::npos) << number << ": " << err;
  }
  const auto lf = fit_json(write(t.path / "lf.csv", "v,eps,sigma\n" + kRows));
  std::string cr = "v,eps,sigma\n" + kRows;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  std::string crlf;
  for (const char c : "v,eps,sigma\n" + kRows) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(fit_json(write(t.path / "cr.csv", cr))["fits"], lf["fits"]);
  EXPECT_EQ(fit_json(write(t.path / "crlf.csv", crlf))["fits"], lf["fits"]);
  // Data below eps at the dash-pot's naive edge: the message says which edge, as docs/fit.md does.
  const auto low = write(t.path / "low.csv", "v,eps\n1,1e-40\n2,2e-40\n");
  const auto r = run_cli("fit-data " + low + " --law linear-dashpot --speed-independent-end naive --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto fit = nlohmann::json::parse(r.out)["fits"][0];
  EXPECT_EQ(fit["status"], "at-edge");
  const std::string message = fit["message"].get<std::string>();
  const std::string phrase = "the edge of the naive end's range";
  EXPECT_NE(message.find(phrase), std::string::npos) << message;
  EXPECT_NE(slurp(std::string(RESTITUTION_SOURCE_DIR) + "/docs/fit.md").find(phrase), std::string::npos);
}

// Item 10: the usual spellings, RFC 4180 quoting and an index column give the same fit; ambiguity is refused.
TEST(FitDataInput, UsualColumnNamesQuotingAndIndexColumns) {
  const TempFolder t;
  const auto canonical = fit_json(write(t.path / "c.csv", "v,eps,sigma\n" + kRows));
  const std::string indexed_rows = "0,0.5,0.8,0.01\n1,1,0.78,0.01\n2,2,0.75,0.01\n3,4,0.71,0.01\n";
  for (const std::string& header :
       {"velocity,e,error", "speed,cor,uncertainty", "impact_speed,epsilon,std", "v_m_s,restitution,stderr",
        "speed_m_s,coefficient_of_restitution,eps_err", "\"velocity [m/s]\",E,SIGMA", "\"v (m/s)\",eps,sd",
        "Impact Speed (m/s),Coefficient of Restitution,Std Dev", "\"v\",\"eps\",\"sigma\""}) {
    const auto j = fit_json(write(t.path / "h.csv", header + "\n" + kRows));
    EXPECT_EQ(j["fits"], canonical["fits"]) << header;
  }
  for (const std::string& header : {",v,eps,sigma", "Unnamed: 0,v,eps,sigma", "\"\",v,eps,sigma"}) {
    const auto j = fit_json(write(t.path / "i.csv", header + "\n" + indexed_rows));
    EXPECT_EQ(j["fits"], canonical["fits"]) << header;
  }
  // Quoted fields, a doubled quote in a comment-free header name, blanks around quotes.
  const auto quoted = fit_json(write(t.path / "q.csv",
                                     "\"v\", \"eps\" ,sigma\n\"0.5\",\"0.8\",0.01\n1, \"0.78\" ,0.01\n"
                                     "\"2\",0.75,\"0.01\"\n4,0.71,0.01\n"));
  EXPECT_EQ(quoted["fits"], canonical["fits"]);
  std::string err = refusal("fit-data " + write(t.path / "two.csv", "v,velocity,eps\n1,1,0.5\n"));
  EXPECT_NE(err.find("columns 'v' and 'velocity' both name the speed"), std::string::npos) << err;
  EXPECT_NE(err.find("columns found: 'v', 'velocity', 'eps'; names accepted: speed [m/s]: v velocity"),
            std::string::npos)
      << err;
  err = refusal("fit-data " + write(t.path / "cm.csv", "\"v [cm/s]\",eps\n1,0.5\n2,0.4\n"));
  EXPECT_NE(err.find("a speed in 'cm/s': give the speed in m/s"), std::string::npos) << err;
  err = refusal("fit-data " + write(t.path / "kmh.csv", "speed_km_h,eps\n1,0.5\n2,0.4\n"));
  EXPECT_NE(err.find("a speed in 'km_h'"), std::string::npos) << err;
  err = refusal("fit-data " + write(t.path / "none.csv", "time,eps\n1,0.5\n2,0.4\n"));
  EXPECT_NE(err.find("unknown column 'time'"), std::string::npos) << err;
  err = refusal("fit-data " + write(t.path / "open.csv", "v,eps\n\"1,0.5\n2,0.4\n"));
  EXPECT_NE(err.find(":2:1: a quote opened here is never closed"), std::string::npos) << err;
}

}  // namespace
}  // namespace restitution
