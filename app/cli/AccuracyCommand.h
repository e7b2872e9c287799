#pragma once

namespace vct::cli {

/**
 * `vct-bench accuracy SCENE --sweep spec.json (--reference ref.pfm | --reference-spp N) [--out DIR]`: renders
 * the scene under every point of a sweep spec (AccuracySweep), times full frames on the GPU and measures the
 * error against the reference; also times the path tracer at increasing samples per pixel. Writes
 * DIR/points/point-K.csv per point and merges them into DIR/results.csv, results.md, accuracy.svg/.png (VCT
 * and the path tracer) and accuracy-vct.svg/.png (the VCT settings alone, linear error axis).
 * `--emit-jobs` prints one command per point instead (`--only-point K`), `--merge DIR` collects their files.
 * Builds its own QGuiApplication (offscreen) because PNG text needs one.
 */
class AccuracyCommand {
public:
    static int run(int argc, char** argv);
};

} // namespace vct::cli
