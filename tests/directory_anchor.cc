// Files written through an anchored directory (output/directory_anchor.h)
// go into the directory the path named when it was anchored, whatever
// happens to the name later: a directory put in its place under the same
// name receives nothing, a removed one takes no new file (the write
// fails), and messages show the user's path, not /proc/self/fd/N. A
// directory other than the expected one (device, inode) is refused.

#include <deal.II/base/exceptions.h>

#include <bilayer/output/directory_anchor.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/stat.h>

#include "verdict.h"

using namespace bilayer;
namespace fs = std::filesystem;

namespace
{
  struct stat
  status_of(const std::string &path)
  {
    struct stat s = {};
    ::stat(path.c_str(), &s);
    return s;
  }

  bool
  write(const std::string &path)
  {
    std::ofstream out(path);
    out << "bilayer\n";
    out.close();
    return static_cast<bool>(out);
  }
} // namespace


int
main()
{
  const fs::path work = fs::absolute("directory_anchor.work");
  fs::remove_all(work);
  fs::create_directories(work);
  const std::string staging = (work / "out.partial").string();
  fs::create_directory(staging);
  const struct stat own = status_of(staging);

  const std::string anchored =
    anchor_directory(staging, own.st_dev, own.st_ino);
  std::cout << "anchored through /proc/self/fd: "
            << yes(anchored.rfind("/proc/self/fd/", 0) == 0) << std::endl;

  // Replaced under its name: the files go into the original directory.
  fs::rename(staging, work / "moved");
  fs::create_directory(staging);
  write(staging + "/mine.txt");
  const bool written = write(anchored + "/interface-00.csv");
  std::cout << "a file written after the directory was replaced lands in "
               "the original: "
            << yes(written && fs::exists(work / "moved" / "interface-00.csv"))
            << std::endl
            << "the directory put in its place receives nothing: "
            << yes(!fs::exists(staging + "/interface-00.csv") &&
                   fs::exists(staging + "/mine.txt"))
            << std::endl;

  // Removed: no new file.
  fs::remove_all(work / "moved");
  std::cout << "a removed directory takes no new file: "
            << yes(!write(anchored + "/interface-01.csv")) << std::endl;

  // Messages name the user's path (and /proc/self/fd/N1 is left alone
  // when N is anchored).
  const std::string message = "cannot create '" + anchored + "/x.csv'";
  std::cout << "messages show the user's path: "
            << yes(unanchored(message) ==
                     "cannot create '" + staging + "/x.csv'" &&
                   unanchored(anchored + "1/y") == anchored + "1/y")
            << std::endl;

  // Another directory than the expected one is refused.
  bool refused = false;
  try
    {
      anchor_directory(staging, own.st_dev, own.st_ino);
    }
  catch (const dealii::ExceptionBase &)
    {
      refused = true;
    }
  std::cout << "a directory other than the staging directory refused: "
            << yes(refused) << std::endl;
  fs::remove_all(work);
}
