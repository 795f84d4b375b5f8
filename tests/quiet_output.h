#ifndef bilayer_tests_quiet_output_h
#define bilayer_tests_quiet_output_h

#include <string>

/// The Output section of a test's scene: the records in results/, no VTU,
/// no interface CSV, no progress lines, the terminal reporting the checks
/// only (appended after the scene's own text).
inline std::string
quiet_output()
{
  return "subsection Output\n set Output directory = results\n"
         " set Write VTU = false\n set Write interface CSV = false\n"
         " set Progress interval = 0\n"
         " set Terminal output = checks\nend\n";
}

#endif
