// The report's words: numbers and vectors as it writes them, and the report as text (what
// `springlab homework check` prints, in the current language) and as JSON (for a course's grader).
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "parts.hpp"

namespace springlab::homework {

const char* step_name(Step step) {
  return step == Step::Euler ? "simulateEuler" : "simulateVerlet";
}

std::string num(double value) {
  return format_text("%.4g", value);
}

std::string vec(const Vec2& v) {
  return "(" + num(v.x()) + ", " + num(v.y()) + ")";
}

std::pair<std::string, std::string> apart(const Vec2& a, const Vec2& b) {
  // 4 significant digits, or as many more as it takes for the two to read differently.
  for (int digits = 4; digits <= 17; ++digits) {
    auto text = [digits](const Vec2& v) {
      return "(" + format_text("%.*g", digits, v.x()) + ", " + format_text("%.*g", digits, v.y()) +
             ")";
    };
    if (text(a) != text(b) || digits == 17) return {text(a), text(b)};
  }
  return {vec(a), vec(b)};
}

std::string call_text(Step step, int step_number, int steps, double h) {
  return format_text(tr("%s (step %d of %d, h = %s)"), step_name(step), step_number, steps,
                     step_text(h).c_str());
}

std::string threw_text(const std::string& call, const std::string& what) {
  return format_text(tr("%s threw an exception: %s"), call.c_str(), what.c_str());
}

std::string timed_out_text(const std::string& call, double seconds) {
  return format_text(tr("%s did not return within %s s and was stopped (an endless loop?)"),
                     call.c_str(), format_text("%.3g", seconds).c_str());
}

std::string ended_text(const std::string& call, const std::string& how) {
  return how.empty() ? format_text(tr("%s ended the program"), call.c_str()) : call + " " + how;
}

std::string printed_text(const std::string& printed) {
  return format_text(tr("; it printed: %s"), printed.c_str());
}

std::string library_check_text(const std::string& printed) {
  // libstdc++'s own words (_GLIBCXX_ASSERTIONS): "...stl_vector.h:1123: ... operator[](size_type)
  // [with ...]: Assertion '__n < this->size()' failed."
  const std::size_t at = printed.find("Assertion '");
  if (at == std::string::npos || printed.find("/c++/") == std::string::npos) return "";
  const std::size_t end = printed.find("' failed", at);
  const std::string check =
      printed.substr(at + 11, end == std::string::npos ? std::string::npos : end - at - 11);
  if (check == "__n < this->size()")
    return tr(
        "read or wrote a std::vector at an index not below its size() (the standard "
        "library's bounds check, on in the checker, stopped it: without it the read is "
        "whatever lies past the end)");
  if (check == "!this->empty()")
    return tr(
        "called front(), back() or pop_back() on an empty std::vector (the standard "
        "library's check, on in the checker, stopped it)");
  return format_text(tr("failed a check of the standard library's, on in the checker: %s"),
                     check.c_str());
}

std::string step_text(double h) {
  const double inverse = 1.0 / h;
  if (inverse >= 2.0 && inverse == std::round(inverse) && inverse < 1e9)
    return "1/" + std::to_string(static_cast<long long>(inverse)) + " s";
  return num(h) + " s";
}

bool any_failed(const CheckSection& s) {
  return std::any_of(s.lines.begin(), s.lines.end(),
                     [](const CheckLine& l) { return l.kind == CheckLine::Fail; });
}

namespace {

int count(const Report& report, CheckLine::Kind kind) {
  int n = 0;
  for (const CheckSection& s : report.sections)
    n += static_cast<int>(std::count_if(s.lines.begin(), s.lines.end(),
                                        [kind](const CheckLine& l) { return l.kind == kind; }));
  return n;
}

const char* kind_word(CheckLine::Kind kind) {
  return kind == CheckLine::Pass ? "ok" : kind == CheckLine::Fail ? "fail" : "note";
}

nlohmann::json step_json(const Identified& found) {
  nlohmann::json j;
  j["method"] = found.method.empty() ? nlohmann::json(nullptr) : nlohmann::json(found.method);
  j["velocity_verlet"] = found.velocity_verlet;
  j["constraints"] = found.constraints;
  j["damping"] = {{"drag", found.damping.drag},
                  {"drag_is_rate", found.damping.drag_rate},
                  {"drag_per_step", found.damping.drag_step},
                  {"drag_taken", found.damping.drag_at == DragAt::Forces        ? "with_forces"
                                 : found.damping.drag_at == DragAt::NewVelocity ? "new_velocity"
                                                                                : "after_position"},
                  {"along_spring", found.damping.along},
                  {"relative_velocity", found.damping.relative},
                  {"verlet", found.damping.verlet},
                  {"verlet_whole_displacement", found.damping.verlet_whole}};
  j["deviation"] = found.deviation;
  j["in_float"] = found.in_float;
  return j;
}

}  // namespace

int Report::passed() const {
  return count(*this, CheckLine::Pass);
}
int Report::failed() const {
  return count(*this, CheckLine::Fail);
}

std::vector<std::string> Report::failed_keys() const {
  std::vector<std::string> keys;
  for (const CheckSection& s : sections)
    for (const CheckLine& l : s.lines)
      if (l.kind == CheckLine::Fail) keys.push_back(l.key);
  return keys;
}

std::string format_report(const Report& report) {
  std::string out;
  for (const CheckSection& s : report.sections) {
    out += s.title + "\n";
    for (const CheckLine& l : s.lines)
      out += (l.kind == CheckLine::Pass   ? "  ok    "
              : l.kind == CheckLine::Fail ? "  FAIL  "
                                          : "        ") +
             l.text + "\n";
  }
  return out + format_text(tr("%d checks passed, %d failed.\n"), report.passed(), report.failed());
}

std::string report_json(const Report& report) {
  nlohmann::json j;
  j["passed"] = report.passed();
  j["failed"] = report.failed();
  j["springlab_rope"] = report.springlab_rope;
  j["constructor_wrong"] = report.constructor_wrong;
  j["steps"] = {{step_name(Step::Euler), step_json(report.euler)},
                {step_name(Step::Verlet), step_json(report.verlet)}};
  j["sections"] = nlohmann::json::array();
  for (const CheckSection& s : report.sections) {
    nlohmann::json lines = nlohmann::json::array();
    for (const CheckLine& l : s.lines)
      lines.push_back({{"kind", kind_word(l.kind)}, {"key", l.key}, {"text", l.text}});
    j["sections"].push_back({{"title", s.title}, {"lines", lines}});
  }
  // Invalid UTF-8 in a student's printed output (a crash's last lines) is replaced, never thrown.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace springlab::homework
