// voxc: the voxel grammar compiler. Exit codes: 0 success, 1 the user's error, 2 internal error.
#include "Commands.h"
#include "Console.h"
#include "Depfile.h"

#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    voxc::installTempFileCleanup(); // before any file is written
    CLI::App app{"voxc: compiles .vox voxel grammar files to Vulkan compute kernels and runs them"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "voxc 0.1.0");
    voxc::driver::addCheckCommand(app);
    voxc::driver::addCompileCommand(app);
    voxc::driver::addRunCommand(app);
    voxc::driver::addRenderCommand(app);
    voxc::driver::addInterpCommand(app);
    voxc::driver::addExploreCommand(app);
    voxc::driver::addLsystemCommand(app);
    voxc::driver::addEvolveCommand(app);
    voxc::driver::addTerrainCommand(app);
    voxc::driver::addLspCommand(app);
    voxc::driver::addWorldCommand(app);
    voxc::driver::addViewCommand(app);
    std::vector<std::string> arguments = voxc::driver::spellDepfileFlagsLong(argc, argv);
    std::vector<char*> argumentPointers;
    for (std::string& argument : arguments) argumentPointers.push_back(argument.data());
    try {
        app.parse(int(argumentPointers.size()), argumentPointers.data());
        return 0;
    } catch (const CLI::Success& success) {
        return app.exit(success); // --help, --version
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        return 1;
    } catch (const voxc::driver::DiagnosticsFailed& failure) {
        voxc::driver::printDiagnosticsSummary(failure);
        return 1;
    } catch (const voxc::UserError& error) {
        voxc::driver::printFatalError(error.what(), false);
        return 1;
    } catch (const voxc::InternalError& error) {
        voxc::driver::printFatalError(error.what(), true);
        return 2;
    } catch (const std::exception& error) {
        voxc::driver::printFatalError(std::string("internal error: ") + error.what(), true);
        return 2;
    }
}
