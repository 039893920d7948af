// SPDX-License-Identifier: MIT
#include "hostile_support.h"

#include "core/io/preset.h"
#include "ui/charts/motion_chart.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace hostile {

namespace {

struct Snapshot {
    std::string content;
    unsigned mode = 0;
    bool regular = false;
};

std::map<std::string, Snapshot> snapshot(const fs::path& dir)
{
    std::map<std::string, Snapshot> files;
    for (const auto& e : fs::directory_iterator(dir)) {
        struct stat st {};
        if (::lstat(e.path().c_str(), &st) != 0)
            continue;
        Snapshot s;
        s.mode = st.st_mode;
        s.regular = S_ISREG(st.st_mode);
        if (s.regular)
            s.content = readText(e.path());
        files[e.path().filename().string()] = s;
    }
    return files;
}

// A temporary file of the output path: ".NAME.tmpXXXXXX".
std::vector<std::string> tempFiles(const fs::path& dir)
{
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.front() == '.' && name.find(".tmp") != std::string::npos)
            found.push_back(name);
    }
    return found;
}

// Seconds of CPU the child has used (utime + stime from /proc/PID/stat).
double cpuSeconds(pid_t pid)
{
    const std::string stat = readText("/proc/" + std::to_string(pid) + "/stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos)
        return 0.0;
    std::istringstream in(stat.substr(close + 2));
    std::string field;
    double ticks = 0.0;
    for (int i = 0; i < 13 && in >> field; ++i)
        if (i == 11 || i == 12)
            ticks += std::atof(field.c_str());
    return ticks / double(::sysconf(_SC_CLK_TCK));
}

pid_t spawn(const Case& c, const fs::path& dir, const fs::path& errPath)
{
    // AB_HOSTILE_CLI runs the rows against another build (an older one, to see the cases
    // fail; not as root: an older build replaces the device it is given).
    const char* program = std::getenv("AB_HOSTILE_CLI");
#ifdef AB_WINDOW_PATH
    const std::string path = c.window ? AB_WINDOW_PATH : program ? program : AB_CLI_PATH;
#else
    const std::string path = program ? program : AB_CLI_PATH;
#endif
    std::vector<std::string> args{path};
    args.insert(args.end(), c.args.begin(), c.args.end());
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid != 0)
        return pid;
    // The child: only what is safe after fork, then exec.
    if (::chdir(dir.c_str()) != 0)
        ::_exit(126);
    if (c.window) {
        // No display: a GUI application made before the options are read would abort.
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        ::setenv("QT_QPA_PLATFORM", "xcb", 1);
    }
    rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
    if (c.fileSizeLimit >= 0) {
        ::signal(SIGXFSZ, SIG_IGN); // the write fails with EFBIG, as on a full disk
        rlimit limit{rlim_t(c.fileSizeLimit), rlim_t(c.fileSizeLimit)};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    const int in = ::open("/dev/null", O_RDONLY);
    const bool closed = c.stdoutPath.empty(); // `>&-`: the program starts with no standard output
    const int out = closed ? 0 : ::open(c.stdoutPath.c_str(), O_WRONLY);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0)
        ::_exit(126);
    ::dup2(in, 0);
    if (closed)
        ::close(1);
    else
        ::dup2(out, 1);
    ::dup2(err, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
}

// Waits for the child, at most `seconds` (a hang is a failure, not a wait forever).
bool waitFor(pid_t pid, int& status, double seconds)
{
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid)
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    return false;
}

bool fileExists(const Case& c, const fs::path& dir)
{
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().rfind(c.readyFile, 0) == 0)
            return true;
    return false;
}

// Polls until the child is where the row means to signal it: its file made, then (or
// without a file) some CPU time spent in the work.
bool ready(const Case& c, const fs::path& dir, pid_t pid, double& cpuAtFile)
{
    if (c.readyFile.empty())
        return cpuSeconds(pid) >= 0.3; // past its start, inside the work
    if (cpuAtFile < 0.0) {
        if (!fileExists(c, dir))
            return false;
        cpuAtFile = cpuSeconds(pid);
    }
    return cpuSeconds(pid) - cpuAtFile >= c.readyCpu;
}

std::string checkOutcome(const Case& c, int status, const std::string& err)
{
    std::ostringstream why;
    if (c.dies) {
        if (!WIFSIGNALED(status) || WTERMSIG(status) != c.dies)
            why << "expected death by signal " << c.dies << ", got status " << status << "; ";
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != c.status) {
        why << "expected exit status " << c.status << ", got "
            << (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                                  : "signal " + std::to_string(WTERMSIG(status)))
            << "; ";
    }
    const auto lines = std::count(err.begin(), err.end(), '\n');
    if (lines != c.lines || (!err.empty() && err.back() != '\n'))
        why << "expected " << c.lines << " stderr line(s), got " << lines << "; ";
    if (!c.says.empty() && err.find(c.says) == std::string::npos)
        why << "stderr lacks '" << c.says << "'; ";
    if (err.find('\x1b') != std::string::npos)
        why << "an escape character reached stderr; ";
    return why.str();
}

} // namespace

void writeText(const fs::path& p, const std::string& text, unsigned mode)
{
    std::ofstream(p, std::ios::binary) << text;
    fs::permissions(p, fs::perms(mode), fs::perm_options::replace);
}

std::string readText(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::string repeat(const std::string& s, std::size_t n)
{
    std::string out;
    out.reserve(s.size() * n);
    for (std::size_t i = 0; i < n; ++i)
        out += s;
    return out;
}

Outcome runCase(const Case& c)
{
    char pattern[] = "/tmp/ab-hostile-XXXXXX";
    const char* root = ::mkdtemp(pattern);
    if (!root)
        return {"cannot make a folder"};
    const fs::path dir = fs::path(root) / "work";
    fs::create_directory(dir);
    const fs::path errPath = fs::path(root) / "stderr";
    if (c.prepare)
        c.prepare(dir);
    const auto before = snapshot(dir);

    const pid_t pid = spawn(c, dir, errPath);
    std::string problem;
    int status = 0;
    bool ended = false;
    if (c.signal) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        double cpuAtFile = -1.0;
        while (!ready(c, dir, pid, cpuAtFile) && std::chrono::steady_clock::now() < until &&
               !(ended = ::waitpid(pid, &status, WNOHANG) == pid))
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        if (ended)
            problem += "the program ended before it was signalled; ";
        else
            ::kill(pid, c.signal);
    }
    // A generous bound: the sanitizer build is slow; what is tested is that it ends.
    if (!ended && !waitFor(pid, status, 60.0))
        problem += "the program did not end (killed); ";
    const std::string err = readText(errPath);
    problem += checkOutcome(c, status, err);

    for (const std::string& t : tempFiles(dir))
        problem += "temporary file left: " + t + "; ";
    const auto after = snapshot(dir);
    for (const std::string& name : c.untouched) {
        const auto b = before.find(name), a = after.find(name);
        if (b == before.end())
            problem += "fixture " + name + " missing; ";
        else if (a == after.end())
            problem += name + " was removed; ";
        else if (a->second.mode != b->second.mode)
            problem += name + ": mode changed; ";
        else if (a->second.content != b->second.content)
            problem += name + ": content changed; ";
    }
    for (const std::string& name : c.absent)
        if (after.count(name))
            problem += name + " exists but must not; ";
    if (c.check)
        problem += c.check(dir, err);
    if (!problem.empty())
        problem = c.name + ": " + problem + " stderr: " + err.substr(0, 400);
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(root, ec);
    return {problem};
}

bool chartKeysAgree()
{
    std::vector<std::string> window;
    for (ab::ui::ChartKind k : ab::ui::allChartKinds())
        window.emplace_back(ab::ui::chartKey(k));
    std::vector<std::string> core = ab::presetChartKeys();
    std::sort(window.begin(), window.end());
    std::sort(core.begin(), core.end());
    return window == core;
}

} // namespace hostile
