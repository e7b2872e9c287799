#pragma once

namespace vct::cli {

/** `vct-bench`: measurements written for docs/BENCHMARKS.md. Subcommands: plan. */
class BenchCommand {
public:
    static int run(int argc, char** argv);
};

} // namespace vct::cli
