// SPDX-License-Identifier: MIT
// The rows of the hostile-input suite, by class: output targets, inputs, numbers and
// messages, signals.
#include "hostile_support.h"

#include <sys/stat.h>

namespace hostile {

namespace {

const std::string precious = "precious: a user's file\n";

// A short physical run: no health finding, so nothing on stderr when it succeeds.
std::vector<std::string> quickRun(const std::string& out, const std::string& steps = "20")
{
    return {"run", "bounce1d", "--model", "physical", "--steps", steps, "--out", out};
}

std::string kindOf(const fs::path& p)
{
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0)
        return "missing";
    return S_ISLNK(st.st_mode)    ? "link"
           : S_ISFIFO(st.st_mode) ? "fifo"
           : S_ISCHR(st.st_mode)  ? "chr"
           : S_ISREG(st.st_mode)  ? "file"
                                  : "other";
}

std::string expectKind(const fs::path& p, const std::string& kind)
{
    const std::string k = kindOf(p);
    return k == kind ? "" : p.string() + " is " + k + ", not " + kind + "; ";
}

std::string startsWithHeader(const fs::path& p)
{
    return readText(p).rfind("t,ball,x,y,z,vx,vy,vz\n", 0) == 0 ? "" : p.string() + " lacks the CSV header; ";
}

void fifo(const fs::path& p)
{
    ::mkfifo(p.c_str(), 0644);
}

std::string presetText(const std::string& extra)
{
    return R"({"format": "amazeballs-preset", "version": 1, "name": "x", "scene": "bounce1d", "model": "physical")" +
           extra + "}\n";
}

// A message line of at most `n` bytes (long input is cut, not echoed whole).
auto shorterThan(std::size_t n)
{
    return [n](const fs::path&, const std::string& err) {
        return err.size() <= n ? std::string() : "the line is " + std::to_string(err.size()) + " bytes; ";
    };
}

} // namespace

void addTargetCases(std::vector<Case>& c)
{
    // /dev/zero: a device that takes writes, as /dev/null does (which a shared machine's
    // older builds may have replaced).
    Case device{"device target is written, never replaced", quickRun("/dev/zero"), {}, 0};
    device.lines = 0;
    device.check = [](const fs::path&, const std::string&) { return expectKind("/dev/zero", "chr"); };
    c.push_back(device);

    Case link{"symlink target: the file it names is written", quickRun("link.csv"),
              [](const fs::path& d) {
                  writeText(d / "real.csv", precious);
                  fs::create_symlink("real.csv", d / "link.csv");
              },
              0};
    link.lines = 0;
    link.check = [](const fs::path& d, const std::string&) {
        return expectKind(d / "link.csv", "link") + startsWithHeader(d / "real.csv");
    };
    c.push_back(link);

    Case dangling{"dangling symlink target: the file it names is made", quickRun("link.csv"),
                  [](const fs::path& d) { fs::create_symlink("new.csv", d / "link.csv"); }, 0};
    dangling.lines = 0;
    dangling.check = [](const fs::path& d, const std::string&) {
        return expectKind(d / "link.csv", "link") + startsWithHeader(d / "new.csv");
    };
    c.push_back(dangling);

    Case readOnly{"read-only target is refused, root or not", quickRun("ro.csv"),
                  [](const fs::path& d) { writeText(d / "ro.csv", precious, 0444); }};
    readOnly.says = "read-only";
    readOnly.untouched = {"ro.csv"};
    c.push_back(readOnly);

    Case mode{"existing target keeps its mode", quickRun("keep.csv"),
              [](const fs::path& d) { writeText(d / "keep.csv", precious, 0640); }, 0};
    mode.lines = 0;
    mode.check = [](const fs::path& d, const std::string&) {
        struct stat st {};
        ::stat((d / "keep.csv").c_str(), &st);
        return ((st.st_mode & 07777) == 0640 ? std::string() : "mode not kept; ") + startsWithHeader(d / "keep.csv");
    };
    c.push_back(mode);

    Case pipe{"FIFO target without a reader is refused, not waited on", quickRun("out.fifo"),
              [](const fs::path& d) { fifo(d / "out.fifo"); }};
    pipe.says = "no reader";
    pipe.check = [](const fs::path& d, const std::string&) { return expectKind(d / "out.fifo", "fifo"); };
    c.push_back(pipe);

    Case folder{"folder target is refused", quickRun("sub"),
                [](const fs::path& d) { fs::create_directory(d / "sub"); }};
    folder.says = "folder";
    c.push_back(folder);

    Case missing{"target in a missing folder is refused", quickRun("nosuch/x.csv")};
    missing.says = "does not exist";
    c.push_back(missing);

    Case full{"full disk: CSV refused in one line, the old file kept", quickRun("big.csv", "5000"),
              [](const fs::path& d) { writeText(d / "big.csv", precious); }, 4};
    full.fileSizeLimit = 4096;
    full.says = "the old file is kept";
    full.untouched = {"big.csv"};
    c.push_back(full);

    for (const char* ext : {"svg", "png"}) {
        Case image{std::string("full disk: figure ") + ext + " refused in one line",
                   {"figure", "2.5", "--out", std::string("f.") + ext},
                   {},
                   4};
        image.fileSizeLimit = 2048;
        image.says = "not written";
        image.absent = {std::string("f.") + ext};
        c.push_back(image);
    }
    Case chart{"full disk: chart SVG refused in one line",
               {"chart", "many-balls", "--chart", "energy", "--steps", "100", "--out", "c.svg"},
               {},
               4};
    chart.fileSizeLimit = 4096;
    chart.says = "not written";
    chart.absent = {"c.svg"};
    c.push_back(chart);

    Case stdoutRun{"full standard output: run", {"run", "bounce1d", "--model", "physical", "--steps", "50"}, {}, 4};
    stdoutRun.stdoutPath = "/dev/full";
    stdoutRun.says = "standard output";
    c.push_back(stdoutRun);
    Case stdoutSummary = stdoutRun;
    stdoutSummary.name = "full standard output: run --summary";
    stdoutSummary.args.push_back("--summary");
    c.push_back(stdoutSummary);
    Case stdoutClosed{
        "closed standard output: run names it once", {"run", "bounce1d", "--model", "physical", "--steps", "5"}, {}, 4};
    stdoutClosed.stdoutPath.clear();
    stdoutClosed.says = "standard output: not written: it is closed (Bad file descriptor)";
    c.push_back(stdoutClosed);
    Case stdoutList{"full standard output: list", {"list"}, {}, 4};
    stdoutList.stdoutPath = "/dev/full";
    stdoutList.says = "standard output";
    c.push_back(stdoutList);

    const std::string longName = repeat("a", 246) + ".csv"; // 250 bytes: fits a 255-byte limit
    Case name{"a 250-character name is written", quickRun(longName), {}, 0};
    name.lines = 0;
    name.check = [longName](const fs::path& d, const std::string&) { return startsWithHeader(d / longName); };
    c.push_back(name);
}

void addInputCases(std::vector<Case>& c)
{
    Case init{"--init FIFO is refused without waiting",
              {"run", "many-balls", "--init", "in.csv"},
              [](const fs::path& d) { fifo(d / "in.csv"); }};
    init.says = "FIFO";
    c.push_back(init);
    Case preset{"--preset FIFO is refused without waiting",
                {"run", "bounce1d", "--preset", "p.json"},
                [](const fs::path& d) { fifo(d / "p.json"); }};
    preset.says = "FIFO";
    c.push_back(preset);
    c.push_back({"--init device is refused, not read",
                 {"run", "many-balls", "--init", "/dev/zero"},
                 {},
                 2,
                 0,
                 1,
                 "character device"});
    c.push_back({"--preset device is refused, not read",
                 {"run", "bounce1d", "--preset", "/dev/zero"},
                 {},
                 2,
                 0,
                 1,
                 "character device"});
    c.push_back({"--init folder is named a folder",
                 {"run", "many-balls", "--init", "d"},
                 [](const fs::path& d) { fs::create_directory(d / "d"); },
                 2,
                 0,
                 1,
                 "folder"});
    c.push_back({"--init without a name says so", {"run", "many-balls", "--init", ""}, {}, 2, 0, 1, "no file name"});
    c.push_back({"--init missing file", {"run", "many-balls", "--init", "none.csv"}, {}, 2, 0, 1, "no such file"});
    c.push_back({"--init misnamed column",
                 {"run", "many-balls", "--init", "i.csv"},
                 [](const fs::path& d) { writeText(d / "i.csv", "t,ball,x,y,z,vx,vy,vzGARBAGE\n0,0,0,0,0,0,0,0\n"); },
                 2,
                 0,
                 1,
                 "vzGARBAGE"});
    c.push_back({"--init extra column",
                 {"run", "many-balls", "--init", "i.csv"},
                 [](const fs::path& d) { writeText(d / "i.csv", "t,ball,x,y,z,vx,vy,vz,q\n0,0,0,0,0,0,0,0,1\n"); },
                 2,
                 0,
                 1,
                 "one too many"});
    c.push_back({"--init endless line is refused, memory bounded",
                 {"run", "many-balls", "--init", "i.csv"},
                 [](const fs::path& d) { writeText(d / "i.csv", repeat("0", 1 << 20)); },
                 2,
                 0,
                 1,
                 "longer than"});
    c.push_back({"--set n that disagrees with --init",
                 {"run", "many-balls", "--set", "n=10", "--init", "i.csv"},
                 [](const fs::path& d) {
                     writeText(d / "i.csv",
                               "t,ball,x,y,z,vx,vy,vz\n0,0,1,2,3,0,0,0\n0,1,5,2,3,0,0,0\n0,2,9,2,3,0,0,0\n");
                 },
                 2,
                 0,
                 1,
                 "3 balls"});

    std::string keys;
    for (int i = 0; i < 70000; ++i)
        keys += ", \"k" + std::to_string(i) + "\": 0";
    c.push_back({"preset of 70,000 keys is refused in one line",
                 {"run", "bounce1d", "--preset", "p.json"},
                 [keys](const fs::path& d) { writeText(d / "p.json", presetText(keys)); },
                 2,
                 0,
                 1,
                 "unknown key"});
    c.push_back({"preset with a duplicate key among 70,000",
                 {"run", "bounce1d", "--preset", "p.json"},
                 [keys](const fs::path& d) { writeText(d / "p.json", presetText(keys + ", \"k5\": 1")); },
                 2,
                 0,
                 1,
                 "duplicate key"});
    Case digits{"preset number of 900,000 digits is not echoed whole",
                {"run", "bounce1d", "--preset", "p.json"},
                [](const fs::path& d) { writeText(d / "p.json", presetText(", \"dt\": 1" + repeat("0", 900000))); }};
    digits.check = shorterThan(400);
    c.push_back(digits);
    c.push_back(
        {"preset naming an unknown chart",
         {"run", "bounce1d", "--preset", "p.json"},
         [](const fs::path& d) { writeText(d / "p.json", presetText(", \"view\": {\"charts\": [\"nosuchchart\"]}")); },
         2,
         0,
         1,
         "unknown chart"});
    c.push_back({"preset larger than the limit is refused before reading",
                 {"run", "bounce1d", "--preset", "p.json"},
                 [](const fs::path& d) { writeText(d / "p.json", repeat(" ", 3 << 20)); },
                 2,
                 0,
                 1,
                 "larger than"});
}

void addNumberCases(std::vector<Case>& c)
{
    const std::vector<std::string> run{"run", "bounce1d", "--model", "physical"};
    auto with = [&](std::vector<std::string> more) {
        std::vector<std::string> args = run;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    c.push_back({"--t-end beyond the step limit (1e308)", with({"--t-end", "1e308"}), {}, 2, 0, 1, "4e9 steps"});
    c.push_back(
        {"--t-end beyond the step limit (tiny dt)", with({"--t-end", "1", "--dt", "1e-20"}), {}, 2, 0, 1, "4e9 steps"});
    c.push_back({"--t-end beyond the step limit (9.3e18)", with({"--t-end", "9.3e18"}), {}, 2, 0, 1, "4e9 steps"});
    c.push_back({"--t-end at the start gives no step", with({"--t-end", "0"}), {}, 2, 0, 1, "at least one step"});
    c.push_back({"--steps 0 is refused", with({"--steps", "0"}), {}, 2, 0, 1, "--steps"});
    c.push_back({"an underflow is named as such", with({"--set", "k=1e-400"}), {}, 2, 0, 1, "too small"});
    c.push_back({"an integer beyond 2^53 is refused, not rounded",
                 {"run", "many-balls", "--set", "seed=9007199254740993"},
                 {},
                 2,
                 0,
                 1,
                 "2^53"});
    std::vector<std::string> sets = with({"--steps", "1"});
    for (int i = 0; i < 40000; ++i) {
        sets.push_back("--set");
        sets.push_back("g=9.81");
    }
    c.push_back({"40,000 --set are read", sets, {}, 0, 0, 0});
    c.push_back(
        {"a newline in an argument stays on one line", with({"--integrator", "eu\nler"}), {}, 2, 0, 1, "eu\\nler"});
    c.push_back({"an escape sequence in an argument is shown escaped",
                 with({"--integrator", "\x1b[31mred"}),
                 {},
                 2,
                 0,
                 1,
                 "\\x1b[31mred"});
    Case cut{"a long argument is cut with an ellipsis",
             with({"--integrator", repeat("x", 300)}),
             {},
             2,
             0,
             1,
             "\xE2\x80\xA6"};
    cut.check = shorterThan(300);
    c.push_back(cut);
}

void addSignalCases(std::vector<Case>& c)
{
    const std::vector<std::string> longRun{"run",     "many-balls", "--model", "physical",
                                           "--steps", "100000000",  "--out",   "o.csv"};
    const auto prepare = [](const fs::path& d) { writeText(d / "o.csv", precious); };
    for (int sig : {SIGINT, SIGTERM}) {
        Case k{std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") + " during run --out: 130, no file left",
               longRun,
               prepare,
               130,
               0,
               1,
               "interrupted"};
        k.signal = sig;
        k.readyFile = ".o.csv.tmp";
        k.untouched = {"o.csv"};
        c.push_back(k);
    }
    for (int sig : {SIGHUP, SIGQUIT}) {
        Case k{std::string(sig == SIGHUP ? "SIGHUP" : "SIGQUIT") + " during run --out: no temporary file left",
               longRun,
               prepare,
               0,
               sig,
               0};
        k.signal = sig;
        k.readyFile = ".o.csv.tmp";
        k.untouched = {"o.csv"};
        c.push_back(k);
    }
    // One frame of the report's model from its start cube is quadratic in n: the
    // interrupt is honoured inside the frame.
    Case step{"SIGINT inside one long step of the report model",
              {"run", "many-balls", "--model", "report", "--set", "n=300000", "--steps", "3", "--out", "o.csv"},
              prepare,
              130,
              0,
              1,
              "interrupted"};
    step.signal = SIGINT;
    step.readyFile = ".o.csv.tmp";
    step.readyCpu = 0.5; // a frame of 300,000 balls in contact takes minutes: the signal lands inside it
    step.untouched = {"o.csv"};
    c.push_back(step);
    Case bench{
        "SIGINT during bench's timed steps",
        {"bench", "--balls", "20000", "--broadphase", "grid", "--steps", "1000000", "--repeats", "1", "--out", "b.csv"},
        {},
        130,
        0,
        1,
        "interrupted"};
    bench.signal = SIGINT;
    bench.absent = {"b.csv"};
    c.push_back(bench);
}

void addWindowCases(std::vector<Case>& c)
{
#ifdef AB_WINDOW_PATH
    auto window = [&](std::string name, std::vector<std::string> args, int status, int lines, std::string says,
                      std::function<void(const fs::path&)> prepare = {}) {
        Case k{"window, no display: " + name, std::move(args), std::move(prepare), status, 0, lines, std::move(says)};
        k.window = true;
        c.push_back(k);
    };
    window("an unknown option", {"--bogus"}, 2, 1, "bogus");
    window("--version", {"--version"}, 0, 0, "");
    window("--help", {"--help"}, 0, 0, "");
    window("--measure-frames beyond its bound", {"--measure-frames", "3000000"}, 2, 1, "[1, 3600]");
    window("--measure-frames not a number", {"--measure-frames", "abc"}, 2, 1, "not a number");
    window("--measure-frames infinite", {"--measure-frames", "inf"}, 2, 1, "finite");
    window("--threads zero", {"--threads", "0"}, 2, 1, "--threads: 0 is outside [1, 256]");
    window("--threads beyond its bound", {"--threads", "257"}, 2, 1, "[1, 256]");
    window("--threads not a whole number", {"--threads", "2.5"}, 2, 1, "--threads");
    window("a missing preset", {"none.json"}, 2, 1, "no such file");
    window("a FIFO preset", {"p.json"}, 2, 1, "FIFO", [](const fs::path& d) { fifo(d / "p.json"); });
    window("a bad --set", {"--scene", "bounce1d", "--set", "g=abc"}, 2, 1, "not a number");
    window("a misspelt --set name", {"--scene", "bounce1d", "--set", "hh=1"}, 2, 1, "did you mean h0?");
    window("a --set name of no stage", {"--set", "zzzzqq=1"}, 2, 1, "no stage has a parameter 'zzzzqq'");
#else
    (void)c;
#endif
}

} // namespace hostile
