// The reader shared by the plugin's two file formats (restitution_table.h, contact_law.h): the
// lines of a file without its comments, keyword lines and rows of numbers, with errors that name
// the file and the line; and the cubic Hermite polynomial both formats interpolate with. Internal:
// no LAMMPS here.

#ifndef RESTITUTION_TABLE_READER_H
#define RESTITUTION_TABLE_READER_H

#include "restitution_table.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace Restitution {

namespace detail {

  // The cubic Hermite polynomial on [x0, x1] through (x0, y0), (x1, y1) with slopes d0, d1:
  // the same expression as the Python side (PchipTable.__call__, the C header of c_fortran).
  inline double hermite(double x, double x0, double x1, double y0, double y1, double d0, double d1)
  {
    const double h = x1 - x0;
    const double t = (x - x0) / h;
    const double s = 1.0 - t;
    return (1.0 + 2.0 * t) * s * s * y0 + t * s * s * h * d0 + t * t * (3.0 - 2.0 * t) * y1 -
        t * t * s * h * d1;
  }

  // Index lo of the interval [x[lo], x[lo + 1]] holding v (x increasing, x[0] <= v <= x.back()).
  inline std::size_t interval(const std::vector<double> &x, double v)
  {
    auto it = std::upper_bound(x.begin(), x.end(), v);
    std::size_t hi = static_cast<std::size_t>(it - x.begin());
    if (hi >= x.size()) hi = x.size() - 1;
    if (hi == 0) hi = 1;
    return hi - 1;
  }

  // The non-comment lines of a text, each with its line number.
  struct Line {
    int number;
    std::vector<std::string> words;
  };

  inline std::vector<Line> content_lines(const std::string &text)
  {
    std::vector<Line> lines;
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    while (std::getline(in, raw)) {
      ++number;
      std::size_t first = raw.find_first_not_of(" \t\r");
      if (first == std::string::npos || raw[first] == '#') continue;
      std::istringstream words(raw);
      Line line{number, {}};
      std::string word;
      while (words >> word) line.words.push_back(word);
      lines.push_back(line);
    }
    return lines;
  }

  class Reader {
   public:
    Reader(const std::string &text, const std::string &name) :
        lines_(content_lines(text)), name_(name)
    {
    }

    [[noreturn]] void fail(const std::string &what) const
    {
      int number = pos_ < lines_.size() ? lines_[pos_].number : -1;
      std::string where = number > 0 ? " line " + std::to_string(number) : " at its end";
      throw TableError("restitution table " + name_ + where + ": " + what);
    }

    const Line &next(const std::string &expected)
    {
      if (pos_ >= lines_.size()) fail("ends early; expected " + expected);
      return lines_[pos_++];
    }

    // A keyword line "key v1 v2 ..." with exactly nwords words in all.
    const Line &keyword(const std::string &key, std::size_t nwords, const std::string &form)
    {
      const Line &line = next("'" + form + "'");
      if (line.words[0] != key || line.words.size() != nwords) {
        --pos_;
        fail("expected '" + form + "'");
      }
      return line;
    }

    double number(const Line &line, std::size_t i)
    {
      const std::string &word = line.words.at(i);
      char *end = nullptr;
      errno = 0;
      double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
        --pos_;
        fail("'" + word + "' is not a finite number");
      }
      return value;
    }

    long count(const Line &line, std::size_t i)
    {
      const std::string &word = line.words.at(i);
      char *end = nullptr;
      long value = std::strtol(word.c_str(), &end, 10);
      if (end == word.c_str() || *end != '\0' || value < 2) {
        --pos_;
        fail("'" + word + "' is not a count of at least 2");
      }
      return value;
    }

    // n rows of three numbers each.
    void rows(long n, std::vector<double> &a, std::vector<double> &b, std::vector<double> &c,
              const std::string &form)
    {
      for (long k = 0; k < n; ++k) {
        const Line &line = next("a row '" + form + "'");
        if (line.words.size() != 3) {
          --pos_;
          fail("expected a row '" + form + "'");
        }
        a.push_back(number(line, 0));
        b.push_back(number(line, 1));
        c.push_back(number(line, 2));
      }
    }

    // An integer in [lo, hi].
    long integer(const Line &line, std::size_t i, long lo, long hi)
    {
      const std::string &word = line.words.at(i);
      char *end = nullptr;
      long value = std::strtol(word.c_str(), &end, 10);
      if (end == word.c_str() || *end != '\0' || value < lo || value > hi) {
        --pos_;
        fail("'" + word + "' is not an integer from " + std::to_string(lo) + " to " +
             std::to_string(hi));
      }
      return value;
    }

    // The next line's first word, without taking the line ("" at the end).
    std::string peek() const { return pos_ < lines_.size() ? lines_[pos_].words[0] : ""; }

    bool done() const { return pos_ >= lines_.size(); }

   private:
    std::vector<Line> lines_;
    std::string name_;
    std::size_t pos_ = 0;
  };

}    // namespace detail

}    // namespace Restitution

#endif
