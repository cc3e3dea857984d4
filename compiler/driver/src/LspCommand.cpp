#include "Commands.h"
#include "Console.h"

#include "voxc/lsp/Server.h"

#include <cstdlib>
#include <iostream>

namespace voxc::driver {

void addLspCommand(CLI::App& app) {
    CLI::App* command = app.add_subcommand(
        "lsp", "Serve the Language Server Protocol on stdin/stdout: diagnostics, hover and completion for editors");
    addConsoleFlags(*command); // -q silences the server's log on stderr
    command->callback([] {
        // Binary streams: Content-Length counts bytes, so nothing may translate them.
        std::ios::sync_with_stdio(false);
        std::exit(lsp::serve(std::cin, std::cout, status()));
    });
}

} // namespace voxc::driver
