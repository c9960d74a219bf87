#include <signorini/file_output.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace signorini
{
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".part";
    {
      std::ofstream out(temporary, std::ios::binary);
      if (out)
        write(out);
      out.close();
      if (!out)
        {
          std::remove(temporary.c_str());
          throw std::runtime_error("cannot write '" + path + "'");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write '" + path + "'");
      }
  }
} // namespace signorini
