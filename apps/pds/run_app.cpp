// run_app: the exit codes and error lines of pds and pds-mpi (commands.h).

#include <iostream>
#include <new>

#include "commands.h"
#include "pds/error.h"

namespace pds::cli {

int run_app(CLI::App& app, int argc, char** argv, bool quiet_usage_errors) {
  const std::string name = app.get_name();
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
    if (!quiet_usage_errors) std::cerr << name << ": error: " << e.what() << " (see " << name << " --help)\n";
    return 2;
  } catch (const pds::InvalidArgument& e) {
    if (!quiet_usage_errors) std::cerr << name << ": error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << name << ": failure: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << name << ": failure: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace pds::cli
