// pds: Poisson disk and blue-noise sampling from the command line.
// Exit status: 0 success, 2 bad usage or input, 1 failure.

#include <iostream>
#include <new>

#include "commands.h"
#include "pds/error.h"
#include "terminal.h"

int main(int argc, char** argv) {
  CLI::App app{"pds: Poisson disk and blue-noise sampling.\n"};
  app.name("pds");
  app.require_subcommand(1);
  app.footer(pds::cli::methods_help());
  pds::cli::add_generate(app);
  pds::cli::add_analyze(app);
  pds::cli::add_methods(app);
  pds::cli::add_compare(app);
  pds::cli::add_tile(app);
  pds::cli::add_render(app);
  pds::cli::add_render_sheet(app);
  pds::cli::add_unbounded(app);
  pds::cli::install_interrupt_handler();
  try {
    app.parse(argc, argv);
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "pds: error: " << e.what() << " (see pds --help)\n";
    return 2;
  } catch (const pds::InvalidArgument& e) {
    std::cerr << "pds: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "pds: failure: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "pds: failure: " << e.what() << "\n";
    return 1;
  }
}
