// vct-fit-ltc: fits the linearly transformed cosines of the Phong lobe (scene/PhongLtcFitter) and writes them
// as the C++ initialiser renderer/scene/PhongLtcTable.inc compiles in. Offline: the table is committed, and
// tests/unit/tst_PhongLtc checks it against the lobe and against a fresh fit.
#include "scene/PhongLobe.h"
#include "scene/PhongLtcFitter.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <thread>

int main(int argc, char** argv)
{
    using namespace vct::render;
    if (argc != 3 || std::strcmp(argv[1], "--out") != 0) {
        std::cerr << "usage: vct-fit-ltc --out renderer/scene/PhongLtcTable.inc\n";
        return 2;
    }
    const std::vector<PhongLtcTable::Cell> cells
        = PhongLtcFitter::fitTable(int(std::max(1u, std::thread::hardware_concurrency())));
    std::ofstream out(argv[2]);
    if (!out) {
        std::cerr << "vct-fit-ltc: cannot write " << argv[2] << '\n';
        return 1;
    }
    out << "// Written by vct-fit-ltc (app/cli/main_fit_ltc.cpp): do not edit. Per cell, row by row "
           "(shininess from\n"
           "// the sharpest down to 0, view from normal to grazing): M^-1 (0,0), (0,2), (2,0), (2,2), the "
           "lobe's "
           "albedo.\n";
    out << std::setprecision(9) << std::showpoint; // "1.00000000f", never "1f"
    for (const PhongLtcTable::Cell& c : cells)
        out << "{ " << c.m00 << "f, " << c.m02 << "f, " << c.m20 << "f, " << c.m22 << "f, " << c.albedo
            << "f },\n";
    if (!out.flush()) {
        std::cerr << "vct-fit-ltc: writing " << argv[2] << " failed\n";
        return 1;
    }
    return 0;
}
