// SPDX-License-Identifier: MIT
// The hostile-input suite's table and its runner: each Case prepares a fresh folder, runs
// the built amazeballs-cli there as a child process (optionally with a file size limit, a
// standard output of /dev/full, a signal once it is ready) and checks the outcome.
#pragma once

#include <csignal>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hostile {

namespace fs = std::filesystem;

struct Case {
    Case(std::string name_, std::vector<std::string> args_, std::function<void(const fs::path&)> prepare_ = {},
         int status_ = 2, int dies_ = 0, int lines_ = 1, std::string says_ = {})
        : name(std::move(name_)), args(std::move(args_)), prepare(std::move(prepare_)), status(status_), dies(dies_),
          lines(lines_), says(std::move(says_))
    {
    }

    std::string name;
    std::vector<std::string> args;                    // after the program name; run in the folder
    std::function<void(const fs::path& dir)> prepare; // fixtures: files, FIFOs, links
    int status = 2;                                   // the exit status, when `dies` is 0
    int dies = 0;                                     // the signal the child must die of
    int lines = 1;                                    // lines on stderr
    std::string says;                                 // a word the stderr line must hold
    std::vector<std::string> untouched;               // files whose content and mode must stay
    std::vector<std::string> absent;                  // files that must not exist afterwards
    std::function<std::string(const fs::path& dir, const std::string& err)> check; // "" or a problem
    bool window = false;                  // runs the window program, without a display (DISPLAY unset, platform xcb)
    std::string stdoutPath = "/dev/null"; // "" closes it (`>&-`)
    long fileSizeLimit = -1;              // bytes, setrlimit(RLIMIT_FSIZE); -1 none
    int signal = 0;                       // sent once the child is ready
    std::string readyFile;                // ready when a file whose name starts so exists; "" when busy on the CPU
    double readyCpu = 0.0;                // and then when it has used this many more CPU seconds (inside its work)
};

struct Outcome {
    std::string problem; // empty when the row passed
};

Outcome runCase(const Case& c);

// Helpers for the fixtures.
void writeText(const fs::path& p, const std::string& text, unsigned mode = 0644);
std::string readText(const fs::path& p);
std::string repeat(const std::string& s, std::size_t n);

void addTargetCases(std::vector<Case>& c);
void addInputCases(std::vector<Case>& c);
void addNumberCases(std::vector<Case>& c);
void addSignalCases(std::vector<Case>& c);
void addWindowCases(std::vector<Case>& c); // none in a build without the window

bool chartKeysAgree();

} // namespace hostile
