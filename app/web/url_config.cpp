#include "web/url_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "lesson/lesson_library.hpp"
#include "options/option_ranges.hpp"
#include "springlab/butcher.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"
#include "util/language.hpp"

namespace springlab::app::web {

namespace {

std::string percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
      out += ' ';
    } else if (text[i] == '%' && i + 2 < text.size() &&
               std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

// Keeps what a link may hold as it is (letters, digits, "-._~,"), the rest as %XX.
std::string percent_encoded(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == ',' || c == '/') {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

double number(const std::string& key, const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x))
    throw InputError("link: " + key + ": must be a number, got '" + text + "'");
  return x;
}

// A number as short as it reads back exactly, with no exponent unless that is shorter: 5000,
// 0.0001, 7.5e-05.
std::string shortest(double x) {
  const auto first_exact = [x](const char* format) {
    char text[64];
    for (int digits = 0; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, format, digits, x);
      if (std::strtod(text, nullptr) == x) break;
    }
    return std::string(text);
  };
  const std::string general = first_exact("%.*g"), fixed = first_exact("%.*f");
  return fixed.size() <= general.size() ? fixed : general;
}

// "My RK 3" -> "my-rk-3": a tableau's name as a method's.
std::string slug(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c))
      out += static_cast<char>(std::tolower(c));
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.empty() ? "link-tableau" : out;
}

// A tableau sent in a link (tableau=<its JSON>), added as a method named after it.
void add_link_tableau(const std::string& json) {
  const ButcherTableau t = parse_tableau(json, "link: tableau");
  add_tableau_method(t, slug(t.name));
}

}  // namespace

AppSettings settings_from_link(const std::string& fragment) {
  AppSettings s;
  std::vector<std::pair<std::string, std::string>> pairs;
  std::stringstream in(fragment.starts_with("#") ? fragment.substr(1) : fragment);
  for (std::string pair; std::getline(in, pair, '&');) {
    if (pair.empty()) continue;
    const std::size_t eq = pair.find('=');
    pairs.emplace_back(percent_decoded(pair.substr(0, eq)),
                       eq == std::string::npos ? "" : percent_decoded(pair.substr(eq + 1)));
  }
  // Tableaux first, wherever they stand in the link: method and compare may name them.
  for (const auto& [key, value] : pairs)
    if (key == "tableau") add_link_tableau(value);
  for (const auto& [key, value] : pairs) {
    if (key == "tableau") continue;
    if (key == "scene")
      s.scene = value;
    else if (key == "method")
      s.sim.method = value;
    else if (key == "dt")
      s.sim.dt = number(key, value);
    else if (key == "substeps")
      s.sim.substeps = value;
    else if (key == "ks")
      s.sim.ks = number(key, value);
    else if (key == "kd")
      s.sim.kd = number(key, value);
    else if (key == "iterations") {
      const double k = number(key, value);
      if (!(k >= kIterations.lo && k <= kIterations.hi && k == std::floor(k)))
        throw InputError("link: iterations: must be a whole number from 1 to 10000, got '" + value +
                         "'");
      s.sim.iterations = static_cast<int>(k);
    } else if (key == "rho")
      s.sim.rho = number(key, value);
    else if (key == "compare")
      s.compare = value;  // (the scene kind's rows: checked once the scene is read)
    else if (key == "compare-layout")
      s.compare_layout = draw::parse_compare_layout(value, "link: compare-layout");
    else if (key == "script")
      s.script = value;
    else if (key == "set")
      s.sim.sets.push_back(value);  // set=cloth.width%3D64, as --set
    else if (key == "lesson")
      s.lesson = value;
    else if (key == "homework") {
      if (value.size() > kMaxHomework)
        throw InputError("link: homework: the code is " + std::to_string(value.size()) +
                         " bytes, more than a link takes (" + std::to_string(kMaxHomework) +
                         "): share the file instead");
      s.homework_js = value;
    } else if (key == "step") {
      const double step = number(key, value);
      if (!(step >= 1 && step <= 12 && step == std::floor(step)))
        throw InputError("link: step: must be a lesson's step number, 1 to 12, got '" + value +
                         "'");
      s.lesson_step = static_cast<int>(step);
    } else if (key == "region") {
      if (value != "0" && value != "1")
        throw InputError("link: region: must be 1 (open the stability region) or 0, got '" + value +
                         "'");
      s.region = value == "1";
    } else if (key == "accuracy") {
      if (value != "0" && value != "1")
        throw InputError(
            "link: accuracy: must be 1 (open the Compare panel and start its sweep) or 0, got '" +
            value + "'");
      s.accuracy = value == "1";
    } else if (key == "lang")
      s.language = check_language(value, "link: lang");
    else if (key == "ui-scale") {
      s.ui_scale = number(key, value);
      check_option("link: ui-scale", s.ui_scale, 0.5, 4.0, false);
    } else {
      throw InputError("link: unknown parameter '" + key + "' (parameters: " + kLinkParameters +
                       ")");
    }
  }
  return s;
}

Opened open_settings(const AppSettings& settings) {
  try {
    Opened opened{prepare(settings.scene, settings.sim), std::nullopt};
    if (settings.script) {
      // A shipped script by name (assets/scripts/NAME.json), or a path.
      std::string path = *settings.script;
      if (path.find('/') == std::string::npos && !path.ends_with(".json"))
        path = (data_dir() / "assets" / "scripts" / (path + ".json")).string();
      opened.script = load_script(path, opened.prepared.scene);
    }
    if (settings.lesson)
      check_lesson_step(open_lesson(*settings.lesson), settings.lesson_step, "link: step");
    return opened;
  } catch (const InputError& e) {
    // The command line's messages name its flags ("--dt: ..."): a link names its parameters.
    std::string message = e.what();
    if (message.starts_with("--"))
      message.erase(0, 2);
    else if (settings.script && message.find("script") != std::string::npos)
      message = "script: " + message;
    throw InputError(message.starts_with("link: ") ? message : "link: " + message);
  }
}

namespace {
// The language spoken, unless English (a link without one opens in its reader's language).
std::string language_part() {
  return current_language() == "en" ? "" : "&lang=" + current_language();
}

// The link's tableau= parts: a shown lane's tableau (every lane's in compare, else the method's)
// travels with the link unless it is a shipped one of that name, named as the lane's method.
std::string link_tableaux(const Session& session) {
  std::string parts;
  std::vector<Method> shown;
  if (session.comparing())
    for (const Lane& l : session.lanes()) shown.push_back(l.sim.settings().method);
  else
    shown.push_back(session.method());
  for (Method m : shown) {
    const ButcherTableau* t = tableau_source(m);
    if (!t) continue;
    std::error_code ec;
    const auto shipped =
        data_dir() / "assets" / "tableaux" / (std::string(method_info(m).name) + ".json");
    bool same = false;
    if (std::filesystem::is_regular_file(shipped, ec)) {
      try {
        same = tableau_json(load_tableau_file(shipped.string())) == tableau_json(*t);
      } catch (const InputError&) {
      }
    }
    if (!same) {
      ButcherTableau named = *t;
      named.name = method_info(m).name;  // so that the link's tableau gets the lane's name back
      parts += "&tableau=" + percent_encoded(tableau_json(named));
    }
  }
  return parts;
}

}  // namespace

std::string link_of(const InteractiveApp& app, const std::vector<std::string>& sets,
                    double ui_scale, const std::string& homework_js) {
  const std::string homework =
      homework_js.empty() ? "" : "&homework=" + percent_encoded(homework_js);
  // In a lesson (the class has not taken over): the lesson at its step.
  if (app.lesson() && !app.interrupted())
    return "lesson=" + percent_encoded(app.lesson()->name) +
           "&step=" + std::to_string(app.step() + 1) +
           (std::abs(ui_scale - 1.0) > 1e-12 ? "&ui-scale=" + shortest(ui_scale) : "") +
           language_part() + homework;
  const Session& session = app.session();
  const Lane& lane = session.primary();
  std::string link = "scene=" + percent_encoded(app.scene_name());
  for (const std::string& set : sets) link += "&set=" + percent_encoded(set);
  // What the scene's own file says, to leave out of the link what has not changed.
  std::optional<Prepared> file;
  try {
    SimOptions as_opened;
    as_opened.sets = sets;
    file = prepare(app.scene_name(), as_opened);
  } catch (const InputError&) {
  }
  const auto differs = [](double a, double b) {
    return std::abs(a - b) > 1e-12 * std::max(std::abs(a), std::abs(b));
  };
  const Model& model = file ? file->scene.model : lane.sim.model();
  const double file_ks = model.materials.empty() ? 0.0 : model.materials.front().ks;
  const double file_kd = model.materials.empty() ? 0.0 : model.materials.front().kd;
  // The homework's lanes are made by its code (homework=) with the rows it puts beside them.
  const bool own = std::any_of(session.lanes().begin(), session.lanes().end(),
                               [](const Lane& l) { return !l.own.empty(); });
  if (!own) link += link_tableaux(session);
  if (own) {
    // (no compare= nor method=: the homework's code makes its lanes and the rows beside them)
  } else if (session.comparing()) {
    std::string lanes;
    for (const Lane& l : session.lanes())
      lanes += (lanes.empty() ? "" : ",") + std::string(lane_row(l).name);
    link += "&compare=" + lanes;
    if (app.ui().view.compare_layout != draw::CompareLayout::Apart)
      link += "&compare-layout=" + std::string(draw::layout_name(app.ui().view.compare_layout));
  } else if (!file || session.method() != file->settings.method) {
    link += "&method=" + std::string(method_info(session.method()).name);
  }
  const double dt = lane.sim.settings().dt;
  if (!file || differs(dt, file->settings.dt)) link += "&dt=" + shortest(dt);
  if (!session.auto_substeps() && (!file || file->settings.auto_substeps ||
                                   lane.sim.settings().substeps != file->settings.substeps))
    link += "&substeps=" + std::to_string(lane.sim.settings().substeps);
  if (differs(session.stiffness(), file_ks)) link += "&ks=" + shortest(session.stiffness());
  if (differs(session.damping(), file_kd)) link += "&kd=" + shortest(session.damping());
  const StepSettings& step = lane.sim.settings().step;
  if (step.iterations > 0) link += "&iterations=" + std::to_string(step.iterations);
  if (step.chebyshev_rho > 0.0) link += "&rho=" + shortest(step.chebyshev_rho);
  if (differs(ui_scale, 1.0)) link += "&ui-scale=" + shortest(ui_scale);
  return link + language_part() + homework;
}

}  // namespace springlab::app::web
