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

JsonWriter& JsonWriter::value(bool truth) {
  next_item(false);
  out_ << (truth ? "true" : "false");
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

namespace {

/// Length of the well-formed UTF-8 sequence that starts `text` (1-4), or 0
/// when it is not one (a stray or overlong byte, a surrogate, a cut sequence).
std::size_t utf8_sequence(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80, high = 0xbf; // allowed range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf)
    length = 2;
  else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) low = 0xa0;  // overlong
    if (lead == 0xed) high = 0x9f; // surrogates
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) low = 0x90;  // overlong
    if (lead == 0xf4) high = 0x8f; // beyond U+10FFFF
  } else
    return 0;
  if (text.size() < length || byte(1) < low || byte(1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (byte(i) < 0x80 || byte(i) > 0xbf) return 0;
  return length;
}

} // namespace

void JsonWriter::write_string(std::string_view text) {
  // JSON text is UTF-8: a byte that does not begin a well-formed sequence
  // (a case file in Latin-1, say) is written as U+FFFD.
  out_ << '"';
  while (!text.empty()) {
    const char ch = text.front();
    const std::size_t length = utf8_sequence(text);
    if (length == 0) {
      out_ << "\\ufffd";
      text.remove_prefix(1);
      continue;
    }
    if (ch == '"' || ch == '\\')
      out_ << '\\' << ch;
    else if (static_cast<unsigned char>(ch) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(ch));
      out_ << escaped;
    } else
      out_ << text.substr(0, length);
    text.remove_prefix(length);
  }
  out_ << '"';
}

std::string JsonWriter::str() const {
  if (!levels_.empty()) throw RunError("internal: summary JSON written with an unclosed object or array");
  return out_.str() + "\n";
}

} // namespace anvil::io
