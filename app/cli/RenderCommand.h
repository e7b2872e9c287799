#pragma once

namespace vct::cli {

/**
 * `vct-render`: renders a scene headlessly and writes the image and, optionally, per-pass statistics.
 * Exit codes: 0 success, 1 bad arguments or input, 2 no GL context, 3 rendering or writing failed,
 * 4 --check-finite found NaN or Inf.
 */
class RenderCommand {
public:
    static int run(int argc, char** argv);
};

} // namespace vct::cli
