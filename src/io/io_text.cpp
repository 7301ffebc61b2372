// Scanning and number helpers shared by the io readers and writers (io_formats.h).
#include "io_formats.h"

#include <fairsurf/mesh/errors.h>

#include <algorithm>
#include <charconv>
#include <system_error>

namespace fairsurf::io_detail {

void Source::fail(const std::string& what) const {
  throw ParseError("read_raw: " + name + ": " + what);
}

int Source::line_at(std::size_t pos) const {
  pos = std::min(pos, bytes.size());
  return 1 + static_cast<int>(std::count(bytes.begin(), bytes.begin() + static_cast<long>(pos), '\n'));
}

namespace {

// std::from_chars rejects a leading '+', which C's strtod and every mesh writer may produce.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  return token;
}

template <typename T>
bool parse_whole(std::string_view token, T& value) {
  token = without_plus(token);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

bool parse_double(std::string_view token, double& value) { return parse_whole(token, value); }
bool parse_float(std::string_view token, float& value) { return parse_whole(token, value); }
bool parse_int64(std::string_view token, long long& value) { return parse_whole(token, value); }

void TextScanner::skip_blanks(bool cross_lines) {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (is_blank(c)) {
      ++pos_;
    } else if (c == '\n' && cross_lines) {
      ++pos_;
    } else if (c == '#' && hash_comments_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

std::string_view TextScanner::next() {
  skip_blanks(true);
  return next_on_line();
}

std::string_view TextScanner::next_on_line() {
  skip_blanks(false);
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n' &&
         !(hash_comments_ && text_[pos_] == '#'))
    ++pos_;
  return text_.substr(start, pos_ - start);
}

void TextScanner::skip_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  if (pos_ < text_.size()) ++pos_;
}

Vertices to_vertices(const std::vector<double>& xyz) {
  Vertices V(static_cast<Eigen::Index>(xyz.size() / 3), 3);
  std::copy(xyz.begin(), xyz.end(), V.data());
  return V;
}

std::size_t safe_reserve(long long count, std::size_t available, std::size_t min_bytes_each) {
  if (count <= 0) return 0;
  return std::min(static_cast<std::size_t>(count), available / std::max<std::size_t>(min_bytes_each, 1) + 1);
}

void IgnoredNotes::add(const std::string& kind, int line) {
  for (auto& entry : entries_)
    if (entry.kind == kind) {
      ++entry.count;
      return;
    }
  entries_.push_back({kind, 1, line});
}

void IgnoredNotes::flush(std::vector<std::string>& notes) const {
  for (const auto& entry : entries_)
    notes.push_back("ignored " + std::to_string(entry.count) + " " + entry.kind + " (first at line " +
                    std::to_string(entry.first_line) + ")");
}

void append_number(std::string& out, double value, int digits) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  out.append(buffer, result.ptr);
}

void append_number(std::string& out, long long value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace fairsurf::io_detail
