#include "cli/BenchCommand.h"

int main(int argc, char** argv)
{
    return vct::cli::BenchCommand::run(argc, argv);
}
