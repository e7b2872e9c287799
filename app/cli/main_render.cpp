#include "cli/RenderCommand.h"

int main(int argc, char** argv)
{
    return vct::cli::RenderCommand::run(argc, argv);
}
