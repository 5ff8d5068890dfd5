#pragma once
// The values every front end's command line shares (the lab shell, rt_render): one
// strict parser for each, so `--size 10x10junk` or `--threads -1` fail the same way
// everywhere. The flags themselves are declared with CLI11 by each front end.
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace wb::cli {

// Largest thread count accepted by --threads (0 means all cores).
constexpr int kMaxThreads = 1024;

// A decimal integer in [lo, hi], digits only (no sign, no spaces, no suffix).
bool parseInt(const std::string& s, int lo, int hi, int& out);

// "WxH", each side a decimal integer in [1, maxSide]; nothing before, between or after.
bool parseSize(const std::string& s, int maxSide, int& width, int& height);

// The message for a refused --size value, e.g. "--size '10x10junk': expected WxH with 1 <= W,H <=
// 8192".
std::string sizeError(const std::string& flag, const std::string& value, int maxSide);

// --threads N: 0 = all cores, else 1..kMaxThreads; false with a message naming the flag.
bool parseThreads(const std::string& flag, const std::string& s, int& threads, std::string& error);

// CLI11 glue: declares `flag` taking WxH / a thread count. A refused value sets `error` to
// the message above and makes CLI11 throw CLI::ValidationError; the caller prints `error`.
CLI::Option* addSizeOption(CLI::App& app, const std::string& flag, int maxSide, int& width,
                           int& height, std::string& error, const std::string& help);
CLI::Option* addThreadsOption(CLI::App& app, const std::string& flag, int& threads,
                              std::string& error, const std::string& help);

// CLI11 reads a value that starts with '-' (e.g. `--keys -+`) as the next flag; the old
// hand-written parsers took the next argument whatever it was. Joins "--flag VALUE" into
// "--flag=VALUE" for every flag in `valueFlags`, so values keep that meaning. An empty
// value (`--out ""`, `--out=`) sets `error` naming the flag and returns nothing: CLI11
// would take the next flag as the value.
std::vector<std::string> joinValues(int argc, const char* const* argv,
                                    const std::vector<std::string>& valueFlags, std::string& error);

} // namespace wb::cli
