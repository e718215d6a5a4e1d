#pragma once
// Reads an MFIX deck (mfix.dat or .mfx: namelist-like `KEY = value` assignments) into one record
// per assigned element: keyword, indices, value text and line. Knows the syntax only (comments
// `!` and `#`, quoted strings, repeats `3*0.0`, value lists that fill consecutive indices,
// logicals, Fortran `d` exponents); what a keyword means is src/app/mfix_import.*.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace bagnold::app::mfix {

struct Record {
  std::string keyword;       // lower case, without indices: "bc_x_w"
  std::vector<int> indices;  // BC_X_W(3) -> {3}; IC_EP_S(2,1) -> {2, 1}; none -> {}
  std::string value;         // the value as written, quotes removed from strings
  bool quoted = false;       // the value was a quoted string
  int line = 0;              // 1-based line of the file

  // "bc_x_w(3)" or "ep_star": how messages name the element.
  std::string name() const;
};

// A syntax error: the line and what is wrong.
class NamelistError : public std::runtime_error {
 public:
  NamelistError(int line, const std::string& what)
      : std::runtime_error(what), line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

// Every assignment in `text`, in the order written.
std::vector<Record> parse_namelist(const std::string& text);

// The value as a real number (`1.0d-3`, `2.5E4`, `7`); nullopt when it is not one.
std::optional<double> as_real(const Record& record);
// The value as a logical (.T., .TRUE., T, .F., .false., F); nullopt when it is not one.
std::optional<bool> as_logical(const Record& record);
// The value as an integer; nullopt when it is not one.
std::optional<int> as_integer(const Record& record);
// The value in upper case, e.g. for 'cgs' or 'Syam_OBrien'.
std::string as_upper(const Record& record);

}  // namespace bagnold::app::mfix
