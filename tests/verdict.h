#ifndef bilayer_tests_verdict_h
#define bilayer_tests_verdict_h

/// The verdict of one check in a test's output: "yes" or "NO".
inline const char *
yes(const bool b)
{
  return b ? "yes" : "NO";
}

#endif
