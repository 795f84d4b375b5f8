#ifndef bilayer_tests_scene_text_h
#define bilayer_tests_scene_text_h

#include <fstream>
#include <sstream>
#include <string>

/// The text of the file @p path (empty where it cannot be read).
inline std::string
file_text(const std::string &path)
{
  std::ifstream      in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// @p text with the line that starts with @p key replaced by @p line (as it
/// was where no line starts so).
inline std::string
replace_line(std::string text, const std::string &key, const std::string &line)
{
  const auto at = text.find(key);
  if (at == std::string::npos)
    return text;
  const auto end = text.find('\n', at);
  return text.replace(at, end - at, line);
}

#endif
