// voxc: the voxel grammar compiler. Exit codes: 0 success, 1 the user's error, 2 internal error.
#include "Commands.h"

#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    voxc::installTempFileCleanup(); // before any file is written
    CLI::App app{"voxc: compiles .vox voxel grammar files to Vulkan compute kernels and runs them"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "voxc 0.1.0");
    voxc::driver::addCheckCommand(app);
    voxc::driver::addCompileCommand(app);
    voxc::driver::addRunCommand(app);
    voxc::driver::addInterpCommand(app);
    voxc::driver::addExploreCommand(app);
    voxc::driver::addLsystemCommand(app);
    voxc::driver::addEvolveCommand(app);
    voxc::driver::addTerrainCommand(app);
    try {
        app.parse(argc, argv);
        return 0;
    } catch (const CLI::Success& success) {
        return app.exit(success); // --help, --version
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        return 1;
    } catch (const voxc::UserError& error) {
        std::cerr << "voxc: error: " << error.what() << "\n";
        return 1;
    } catch (const voxc::InternalError& error) {
        std::cerr << "voxc: " << error.what() << "\nThis is a bug in voxc; please report it with the input file.\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "voxc: internal error: " << error.what() << "\nThis is a bug in voxc; please report it.\n";
        return 2;
    }
}
