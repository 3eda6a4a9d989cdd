// pds: Poisson disk and blue-noise sampling from the command line.
// Exit status: 0 success, 2 bad usage or input, 1 failure.

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
  return pds::cli::run_app(app, argc, argv);
}
