// Runs the luxplan binary for the command-line tests.
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace luxplan::test {

struct CliResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// `COMMAND 2>&1` in the shell, its exit code and output.
inline CliResult runShell(const std::string& commandLine) {
    std::string command = commandLine + " 2>&1";
    CliResult r;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer;
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// `luxplan ARGS` (the binary this build made), its exit code and output.
inline CliResult runCli(const std::string& args) { return runShell(std::string(LUXPLAN_CLI) + " " + args); }

}  // namespace luxplan::test
