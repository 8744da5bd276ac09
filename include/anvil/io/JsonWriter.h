// A small JSON writer for summary.json: objects, arrays, strings escaped,
// numbers with 10 significant digits, non-finite numbers as null (JSON has
// no NaN). Members of an object go one per line; arrays stay on one line
// unless they hold objects.
#pragma once
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace anvil::io {

class JsonWriter {
public:
  JsonWriter();

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// The name of the next member of the enclosing object.
  JsonWriter& key(std::string_view name);
  JsonWriter& value(double number);
  JsonWriter& value(long number);
  JsonWriter& value(int number) { return value(static_cast<long>(number)); }
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(bool truth);
  /// `key(name).value(v)`.
  template <typename T> JsonWriter& member(std::string_view name, const T& v) { return key(name).value(v); }
  /// An array of numbers on one line.
  template <typename T> JsonWriter& array(std::string_view name, const std::vector<T>& values) {
    key(name).begin_array();
    for (const T& v : values)
      value(v);
    return end_array();
  }

  /// The document, ending with a newline; every object and array must be closed.
  std::string str() const;

private:
  struct Level {
    bool object;
    bool empty = true;
  };
  /// Separator and layout before a value or a key.
  void next_item(bool is_object_value);
  void newline();
  /// Opens an object or an array; close() ends the innermost one.
  void open(bool object);
  void close();
  void write_string(std::string_view text);

  std::ostringstream out_;
  std::vector<Level> levels_;
  bool after_key_ = false;
};

} // namespace anvil::io
