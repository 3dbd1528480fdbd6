// A tableau read from JSON (springlab/butcher.hpp; format: assets/tableaux/README.md). Every
// entry is kept as written and checked to be an exact number; a message names the field, the row
// and the column.
#include <cmath>

#include "loading/json_reader.hpp"
#include "methods/rational.hpp"
#include "springlab/butcher.hpp"

namespace springlab {

namespace {

using json_reader::fail_at;
using json_reader::json;

constexpr int kMaxStages = 32;

// The entry's text: a string as written, a number by its shortest decimal (0.1 stays "0.1", 1/10).
TableauEntry entry(const json& value, const std::string& pointer, const std::string& where,
                   const std::string& place) {
  const std::string how = ": write a fraction (\"1/6\"), an integer or a decimal";
  TableauEntry e;
  if (value.is_string()) {
    e.text = value.get<std::string>();
  } else if (value.is_number_integer()) {
    e.text = value.is_number_unsigned() ? std::to_string(value.get<std::uint64_t>())
                                        : std::to_string(value.get<std::int64_t>());
  } else if (value.is_number_float()) {
    e.text = value.dump();  // nlohmann writes the shortest decimal that reads back the same
  } else {
    fail_at(where, pointer, place + " must be a number, " + json_reader::describe(value) + how);
  }
  const std::optional<Rational> r = parse_rational(e.text);
  if (!r) fail_at(where, pointer, place + " \"" + e.text + "\" is not a number" + how);
  e.value = static_cast<double>(*r);
  if (!std::isfinite(e.value))
    fail_at(where, pointer, place + " \"" + e.text + "\" is too large for a step");
  return e;
}

std::vector<TableauEntry> weights(const json* value, const char* key, int stages,
                                  const std::string& where) {
  const std::string pointer = std::string("/") + key;
  if (!value->is_array())
    fail_at(where, pointer,
            std::string(key) + " must be an array of " + std::to_string(stages) + " entries, " +
                json_reader::describe(*value));
  if (static_cast<int>(value->size()) != stages)
    fail_at(where, pointer,
            std::string(key) + " has " + std::to_string(value->size()) + " entries but A has " +
                std::to_string(stages) + " rows: give one a stage");
  std::vector<TableauEntry> out;
  for (std::size_t k = 0; k < value->size(); ++k)
    out.push_back(entry((*value)[k], pointer + "/" + std::to_string(k), where,
                        std::string(key) + " entry " + std::to_string(k + 1)));
  return out;
}

// Row i of A (`row`, i from 0, of `stages` rows): its entries, a short row padded with zeros (a
// row may stop after its last nonzero entry); none nonzero above the diagonal (only explicit and
// diagonally implicit tableaux), and its diagonal entry a_ii >= 0.
std::vector<TableauEntry> tableau_row(const json& row, int i, int stages,
                                      const std::string& where) {
  const std::string pointer = "/A/" + std::to_string(i);
  if (!row.is_array())
    fail_at(
        where, pointer,
        "row " + std::to_string(i + 1) + " of A must be an array, " + json_reader::describe(row));
  if (static_cast<int>(row.size()) > stages)
    fail_at(where, pointer,
            "row " + std::to_string(i + 1) + " of A has " + std::to_string(row.size()) +
                " entries: A must be square, " + std::to_string(stages) + " x " +
                std::to_string(stages) + " (a row may stop after its last nonzero entry)");
  std::vector<TableauEntry> out;
  for (int j = 0; j < stages; ++j) {
    if (j >= static_cast<int>(row.size())) {
      out.push_back({"0", 0.0});
      continue;
    }
    const std::string place =
        "A row " + std::to_string(i + 1) + ", column " + std::to_string(j + 1);
    TableauEntry e =
        entry(row[static_cast<std::size_t>(j)], pointer + "/" + std::to_string(j), where, place);
    if (j > i && e.value != 0.0)
      fail_at(where, pointer + "/" + std::to_string(j),
              place + " is " + e.text +
                  ", above the diagonal: a fully implicit tableau is not supported; "
                  "only explicit (A strictly lower triangular) and diagonally implicit (A lower "
                  "triangular) ones are");
    out.push_back(std::move(e));
  }
  // Q(z) = det(I - z A) = prod (1 - a_ii z): a negative a_ii is a pole of R at z = 1 / a_ii on
  // the negative real axis, where the stage's solve (I - h a_ii J) is singular for a decaying
  // mode.
  const Rational diagonal = *parse_rational(out[static_cast<std::size_t>(i)].text);
  if (diagonal < 0)
    fail_at(where, pointer + "/" + std::to_string(i),
            "A row " + std::to_string(i + 1) + ", column " + std::to_string(i + 1) + " is " +
                out[static_cast<std::size_t>(i)].text +
                ": a negative diagonal entry puts a pole of R(z) at z = " +
                rational_text(Rational(1 / diagonal)) + " on the negative real axis (stage " +
                std::to_string(i + 1) +
                "'s solve is singular where h lambda = " + rational_text(Rational(1 / diagonal)) +
                " for a decaying mode lambda); a diagonally implicit stage needs a_ii >= 0");
  return out;
}

}  // namespace

ButcherTableau parse_tableau(const std::string& json_text, const std::string& where) {
  const json document = json_reader::parse_document(json_text, where);
  if (!document.is_object())
    fail_at(where, "",
            "a tableau must be a JSON object with A and b, " + json_reader::describe(document));
  json_reader::ObjectReader r(document, "", where);
  r.expect({"name", "description", "order", "embedded_order", "A", "b", "c", "b_hat"});
  r.finish();
  ButcherTableau t;
  t.name = r.text("name", "");
  t.description = r.text("description", "");
  if (r.has("order")) t.stated_order = static_cast<int>(r.integer("order", 1, 20));
  if (r.has("embedded_order"))
    t.stated_embedded_order = static_cast<int>(r.integer("embedded_order", 1, 20));

  const json* A = r.raw("A");
  if (!A)
    fail_at(where, "/A",
            "a tableau needs A, its rows of stage coefficients: \"A\": [[0], [\"1/2\"]]");
  if (!A->is_array() || A->empty())
    fail_at(where, "/A", "A must be a non-empty array of rows, " + json_reader::describe(*A));
  t.stages = static_cast<int>(A->size());
  if (t.stages > kMaxStages)
    fail_at(where, "/A",
            "A has " + std::to_string(t.stages) + " rows: at most " + std::to_string(kMaxStages) +
                " stages");
  for (int i = 0; i < t.stages; ++i)
    t.a.push_back(tableau_row((*A)[static_cast<std::size_t>(i)], i, t.stages, where));
  const json* b = r.raw("b");
  if (!b) fail_at(where, "/b", "a tableau needs b, its weights: one a stage");
  t.b = weights(b, "b", t.stages, where);
  if (const json* c = r.raw("c")) {
    t.c = weights(c, "c", t.stages, where);
    t.c_given = true;
  } else {
    for (const auto& row : t.a) {
      Rational sum = 0;
      for (const TableauEntry& e : row) sum += *parse_rational(e.text);
      t.c.push_back({rational_text(sum), static_cast<double>(sum)});
    }
  }
  if (const json* b_hat = r.raw("b_hat")) t.b_hat = weights(b_hat, "b_hat", t.stages, where);
  if (t.stated_embedded_order && !t.b_hat)
    fail_at(where, "/embedded_order", "embedded_order needs b_hat, the embedded method's weights");
  return t;
}

std::string tableau_json(const ButcherTableau& t) {
  const auto texts = [](const std::vector<TableauEntry>& entries) {
    json out = json::array();
    for (const TableauEntry& e : entries) out.push_back(e.text);
    return out;
  };
  json out = json::object();
  if (!t.name.empty()) out["name"] = t.name;
  json rows = json::array();
  for (int i = 0; i < t.stages; ++i) {
    // Each row up to its last nonzero entry, as the format allows.
    std::vector<TableauEntry> row = t.a[static_cast<std::size_t>(i)];
    while (row.size() > 1 && row.back().value == 0.0 && *parse_rational(row.back().text) == 0)
      row.pop_back();
    rows.push_back(texts(row));
  }
  out["A"] = rows;
  out["b"] = texts(t.b);
  if (t.c_given) out["c"] = texts(t.c);
  if (t.b_hat) out["b_hat"] = texts(*t.b_hat);
  return out.dump();
}

ButcherTableau load_tableau_file(const std::string& path) {
  const std::string where = "tableau '" + path + "'";
  return parse_tableau(json_reader::read_document(path, "tableau"), where);
}

}  // namespace springlab
