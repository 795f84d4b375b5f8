#include <bilayer/app/run.h>
#include <bilayer/app/run_environment.h>

// Before every shared library's initialisation: invalid thread counts of
// the environment are hidden from the libraries, and refused by the run.
__attribute__((section(".preinit_array"), used)) static void (
    *const hide_invalid_thread_counts_early)(int, char **, char **) =
  &bilayer::hide_invalid_thread_counts;

int
main(int argc, char **argv)
{
  return bilayer::run_program(argc, argv);
}
