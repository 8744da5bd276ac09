// summary.json holds text from the case file (its title, names): whatever
// bytes that text holds, the document stays valid JSON in UTF-8.
#include "test_common.h"

#include "anvil/io/JsonWriter.h"

#include <string>

namespace {
std::string title_json(const std::string& title) {
  anvil::io::JsonWriter json;
  json.begin_object().member("title", title).end_object();
  return json.str();
}
} // namespace

TEST_CASE("JSON strings escape quotes, backslashes and control characters", "[unit][io]") {
  CHECK(title_json("a\"b\\c\nd\te") == "{\n  \"title\": \"a\\\"b\\\\c\\u000ad\\u0009e\"\n}\n");
}

TEST_CASE("JSON strings keep well-formed UTF-8 and replace every invalid byte by U+FFFD", "[unit][io]") {
  CHECK(title_json("C45 à 1100 °C, ε̄ 𝜎") == "{\n  \"title\": \"C45 à 1100 °C, ε̄ 𝜎\"\n}\n");
  // Latin-1 'é' (a lone 0xe9), a stray continuation byte, an overlong '/',
  // a UTF-16 surrogate, a sequence cut by the end of the text.
  CHECK(title_json("caf\xe9!") == "{\n  \"title\": \"caf\\ufffd!\"\n}\n");
  CHECK(title_json("\x80x") == "{\n  \"title\": \"\\ufffdx\"\n}\n");
  CHECK(title_json("\xc0\xaf") == "{\n  \"title\": \"\\ufffd\\ufffd\"\n}\n");
  CHECK(title_json("\xed\xa0\x80") == "{\n  \"title\": \"\\ufffd\\ufffd\\ufffd\"\n}\n");
  CHECK(title_json("ok\xe2\x82") == "{\n  \"title\": \"ok\\ufffd\\ufffd\"\n}\n");
}
