#include "anvil/io/JsonWriter.h"

#include "anvil/core/error.h"

#include <cmath>
#include <cstdio>

namespace anvil::io {

JsonWriter::JsonWriter() {
  out_.precision(10);
}

void JsonWriter::newline() {
  out_ << '\n' << std::string(2 * levels_.size(), ' ');
}

void JsonWriter::next_item(bool is_object_value) {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (levels_.empty()) return;
  Level& level = levels_.back();
  if (!level.empty) out_ << ',';
  if (level.object || is_object_value)
    newline();
  else if (!level.empty)
    out_ << ' ';
  level.empty = false;
}

void JsonWriter::open(bool object) {
  next_item(object);
  out_ << (object ? '{' : '[');
  levels_.push_back({object});
}

void JsonWriter::close() {
  const Level level = levels_.back();
  levels_.pop_back();
  if (level.object && !level.empty) newline();
  out_ << (level.object ? '}' : ']');
}

JsonWriter& JsonWriter::begin_object() {
  open(true);
  return *this;
}

JsonWriter& JsonWriter::end_object() {
  close();
  return *this;
}

JsonWriter& JsonWriter::begin_array() {
  open(false);
  return *this;
}

JsonWriter& JsonWriter::end_array() {
  close();
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  next_item(false);
  write_string(name);
  out_ << ": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double number) {
  next_item(false);
  if (std::isfinite(number))
    out_ << number;
  else
    out_ << "null";
  return *this;
}

JsonWriter& JsonWriter::value(long number) {
  next_item(false);
  out_ << number;
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  next_item(false);
  write_string(text);
  return *this;
}

void JsonWriter::write_string(std::string_view text) {
  out_ << '"';
  for (const char ch : text) {
    if (ch == '"' || ch == '\\')
      out_ << '\\' << ch;
    else if (static_cast<unsigned char>(ch) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(ch));
      out_ << escaped;
    } else
      out_ << ch;
  }
  out_ << '"';
}

std::string JsonWriter::str() const {
  if (!levels_.empty()) throw RunError("internal: summary JSON written with an unclosed object or array");
  return out_.str() + "\n";
}

} // namespace anvil::io
