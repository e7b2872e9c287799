#pragma once

namespace vct::cli {

/**
 * `vct-bench perf SCENE [--sizes WxH,...] [--grids N,...] [--triangles F,...] [--frames N] [--out DIR]`: runs
 * PerfBenchmark over the scaling curves and writes results.csv, efficiency.csv, memory.csv, perf.md and the
 * charts (SVG and PNG) into DIR. Builds its own QGuiApplication (offscreen) because PNG text needs one.
 */
class PerfCommand {
public:
    static int run(int argc, char** argv);
};

} // namespace vct::cli
