// Reads an MFIX deck into assignment records (src/app/mfix_namelist.hpp).
#include "src/app/mfix_namelist.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace bagnold::app::mfix {

namespace {

struct Token {
  enum Kind { word, quoted, equals } kind;
  std::string text;
  int line;
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool separator(char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; }

// The tokens of one line: words (a word may carry a parenthesized index list), quoted strings
// and '='; comments and namelist group markers (&INPUT_DATA, /, $END) are skipped.
void tokenize_line(const std::string& text, int line, std::vector<Token>& out) {
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (separator(c)) { ++i; continue; }
    if (c == '!' || c == '#') return;
    if (c == '=') { out.push_back({Token::equals, "=", line}); ++i; continue; }
    if (c == '\'' || c == '"') {
      const auto end = text.find(c, i + 1);
      if (end == std::string::npos) throw NamelistError(line, "a string is not closed");
      out.push_back({Token::quoted, text.substr(i + 1, end - i - 1), line});
      i = end + 1;
      continue;
    }
    std::string word;
    while (i < text.size() && !separator(text[i]) && text[i] != '=' && text[i] != '!' &&
           text[i] != '#' && text[i] != '\'' && text[i] != '"') {
      if (text[i] == '(') {
        const auto close = text.find(')', i);
        if (close == std::string::npos) throw NamelistError(line, "a '(' is not closed");
        for (std::size_t k = i; k <= close; ++k)
          if (!std::isspace(static_cast<unsigned char>(text[k]))) word += text[k];
        i = close + 1;
        continue;
      }
      word += text[i++];
    }
    const std::string low = lower(word);
    if (low == "/" || low == "$end" || (!low.empty() && (low[0] == '&' || low[0] == '$'))) continue;
    out.push_back({Token::word, word, line});
  }
}

int to_index(const std::string& text, int line) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0') throw NamelistError(line, "index '" + text + "' is not an integer");
  return static_cast<int>(value);
}

// "bc_x_w(3)" -> keyword "bc_x_w", first index range 3..3, further indices; "spx_dt(1:9)" ->
// range 1..9.
struct Target {
  std::string keyword;
  int first_from = 0, first_to = 0;  // 0: no index
  std::vector<int> rest;
};

Target parse_target(const std::string& word, int line) {
  Target target;
  const auto open = word.find('(');
  target.keyword = lower(word.substr(0, open));
  if (target.keyword.empty() || !std::isalpha(static_cast<unsigned char>(target.keyword[0])))
    throw NamelistError(line, "'" + word + "' is not a keyword");
  if (open == std::string::npos) return target;
  if (word.back() != ')') throw NamelistError(line, "'" + word + "': text after ')'");
  const std::string inside = word.substr(open + 1, word.size() - open - 2);
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= inside.size(); ++k)
    if (k == inside.size() || inside[k] == ',') {
      parts.push_back(inside.substr(start, k - start));
      start = k + 1;
    }
  const auto colon = parts[0].find(':');
  if (colon == std::string::npos) {
    target.first_from = target.first_to = to_index(parts[0], line);
  } else {
    target.first_from = to_index(parts[0].substr(0, colon), line);
    target.first_to = to_index(parts[0].substr(colon + 1), line);
  }
  for (std::size_t k = 1; k < parts.size(); ++k) target.rest.push_back(to_index(parts[k], line));
  return target;
}

struct Value {
  std::string text;
  bool quoted;
  int line;
};

// The values after one '=', with repeats `n*v` expanded.
std::vector<Value> expand_values(const std::vector<Token>& tokens, std::size_t from, std::size_t to) {
  std::vector<Value> values;
  for (std::size_t k = from; k < to; ++k) {
    const Token& t = tokens[k];
    const auto star = t.text.find('*');
    if (t.kind == Token::word && star != std::string::npos && star > 0) {
      const int count = to_index(t.text.substr(0, star), t.line);
      Value value{t.text.substr(star + 1), false, t.line};
      if (value.text.empty()) {  // 3*'NSW': the value is the next (quoted) token
        if (k + 1 >= to) throw NamelistError(t.line, "'" + t.text + "' has no value to repeat");
        value = {tokens[k + 1].text, tokens[k + 1].kind == Token::quoted, t.line};
        ++k;
      }
      for (int n = 0; n < count; ++n) values.push_back(value);
    } else {
      values.push_back({t.text, t.kind == Token::quoted, t.line});
    }
  }
  return values;
}

}  // namespace

std::string Record::name() const {
  if (indices.empty()) return keyword;
  std::string text = keyword + "(";
  for (std::size_t k = 0; k < indices.size(); ++k)
    text += (k ? "," : "") + std::to_string(indices[k]);
  return text + ")";
}

std::vector<Record> parse_namelist(const std::string& text) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= text.size(); ++k)
    if (k == text.size() || text[k] == '\n') {
      tokenize_line(text.substr(start, k - start), line++, tokens);
      start = k + 1;
    }
  auto is_key = [&](std::size_t k) {
    return k + 1 < tokens.size() && tokens[k].kind == Token::word && tokens[k + 1].kind == Token::equals;
  };
  std::vector<Record> records;
  std::size_t k = 0;
  while (k < tokens.size()) {
    if (!is_key(k)) {
      throw NamelistError(tokens[k].line, tokens[k].kind == Token::equals
                                              ? std::string("'=' without a keyword before it")
                                              : "'" + tokens[k].text + "' is not an assignment");
    }
    const Target target = parse_target(tokens[k].text, tokens[k].line);
    const int key_line = tokens[k].line;
    std::size_t end = k + 2;
    while (end < tokens.size() && !is_key(end)) ++end;
    const auto values = expand_values(tokens, k + 2, end);
    if (values.empty()) throw NamelistError(key_line, tokens[k].text + " has no value");
    const bool indexed = target.first_from != 0 || values.size() > 1;
    const int first = target.first_from != 0 ? target.first_from : 1;
    if (target.first_from != 0 && target.first_to != target.first_from &&
        static_cast<int>(values.size()) > target.first_to - target.first_from + 1)
      throw NamelistError(key_line, tokens[k].text + ": more values than the index range holds");
    for (std::size_t n = 0; n < values.size(); ++n) {
      Record record;
      record.keyword = target.keyword;
      if (indexed) {
        record.indices.push_back(first + static_cast<int>(n));
        record.indices.insert(record.indices.end(), target.rest.begin(), target.rest.end());
      }
      record.value = values[n].text;
      record.quoted = values[n].quoted;
      record.line = key_line;
      records.push_back(record);
    }
    // A range with one value fills the whole range: SPX_DT(1:9) = 0.1.
    if (values.size() == 1 && target.first_to > target.first_from)
      for (int index = target.first_from + 1; index <= target.first_to; ++index) {
        Record record = records.back();
        record.indices[0] = index;
        records.push_back(record);
      }
    k = end;
  }
  return records;
}

std::optional<double> as_real(const Record& record) {
  if (record.quoted || record.value.empty()) return std::nullopt;
  std::string text = record.value;
  for (char& c : text)
    if (c == 'd' || c == 'D') c = 'e';
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0') return std::nullopt;
  return value;
}

std::optional<bool> as_logical(const Record& record) {
  if (record.quoted) return std::nullopt;
  std::string text = lower(record.value);
  if (!text.empty() && text[0] == '.') text = text.substr(1);
  if (text.empty()) return std::nullopt;
  if (text[0] == 't' && (text == "t" || text.rfind("true", 0) == 0 || text == "t.")) return true;
  if (text[0] == 'f' && (text == "f" || text.rfind("false", 0) == 0 || text == "f.")) return false;
  return std::nullopt;
}

std::optional<int> as_integer(const Record& record) {
  if (record.quoted || record.value.empty()) return std::nullopt;
  char* end = nullptr;
  const long value = std::strtol(record.value.c_str(), &end, 10);
  if (*end != '\0') return std::nullopt;
  return static_cast<int>(value);
}

std::string as_upper(const Record& record) {
  std::string text = record.value;
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
  return text;
}

}  // namespace bagnold::app::mfix
