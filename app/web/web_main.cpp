// springlab in the browser: the interactive app (platform/interactive_app.hpp) in a WebGL2
// canvas. Only what the browser does differently is here: an OpenGL ES 3 context from
// emscripten's GLFW, a canvas sized to its CSS box times the device pixel ratio (sharp text), the
// frame loop of the page's animation frames, the settings from the page's link, and the files
// the page hands over (a scene from the file picker or dropped on the page).
//
// Sections: the page's state; the frame; the functions the page calls; main.
#include <emscripten.h>
#include <emscripten/html5.h>

#include "gfx/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // (the list of windows, for springlab_layout)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "chart/chart_text.hpp"
#include "chart/text_wrap.hpp"
#include "homework/own_lanes.hpp"
#include "platform/interactive_app.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "ui/homework_status.hpp"
#include "ui/panels.hpp"
#include "ui/theme.hpp"
#include "util/language.hpp"
#include "web/access.hpp"
#include "web/browser.hpp"
#include "web/js_rope.hpp"
#include "web/url_config.hpp"

namespace springlab::app::web {

namespace {

// --- The page's state ----------------------------------------------------------------------

struct Page {
  GLFWwindow* window = nullptr;
  std::unique_ptr<InteractiveApp> app;
  // A browser's animation frames come at the display's rate (60, 120 Hz) with some jitter: one
  // simulated frame every 1/60 s, due a quarter of a frame early.
  FramePacer pacer{1.0 / 60.0, 0.25 / 60.0};
  double ui_scale = 1.0;  // the control's (--ui-scale); the panels' is this times the pixel ratio
  double pixel_ratio = 1.0;
  std::optional<double>
      next_ui_scale;              // applied before the next frame (the fonts are in use during one)
  std::vector<std::string> sets;  // the link's set=..., while its scene is shown
  std::string link;               // the last copied
  long frames = 0;
  double frame_ms = 0.0;   // the last frame's whole time in the app (the browser composites after)
  ImVec4 copy_button;      // where Copy link is (x, y, width, height), for the page's tests
  ImVec4 homework_button;  // and Homework 8's
  draw::Viewport
      scene;  // where the scene is drawn (window pixels from the top left), for the tests
  double css_width = 0, css_height = 0;  // the canvas's CSS box, as the last frame was laid out in
  int win_width = 0, win_height = 0;     // and its size in window pixels (the panels' units)
  // Homework 8 in JavaScript (the page's panel, homework.js): the student's steps as lanes, what
  // the checker found, and their code as the link carries it (homework=).
  HomeworkLanes homework;
  ui::HomeworkStatus homework_status;
  std::string homework_code;
};
Page* g_page = nullptr;

void set_ui_scale(Page& page, double scale) {
  page.ui_scale = std::clamp(scale, 0.5, 4.0);
  page.app->set_scale(static_cast<float>(page.ui_scale * page.pixel_ratio));
  ImGui_ImplOpenGL3_DestroyDeviceObjects();  // the font texture, remade at the new size
}

// The canvas's pixels: its CSS box (index.html sizes it to the window) times the pixel ratio.
// GLFW's window size is the canvas's size in pixels, so the mouse and ImGui count pixels too.
void fit_canvas(Page& page) {
  double css_w = 0, css_h = 0;
  emscripten_get_element_css_size("#canvas", &css_w, &css_h);
  page.css_width = css_w;
  page.css_height = css_h;
  const double ratio = std::clamp(emscripten_get_device_pixel_ratio(), 0.5, 4.0);
  const int w = std::max(1, static_cast<int>(std::lround(css_w * ratio)));
  const int h = std::max(1, static_cast<int>(std::lround(css_h * ratio)));
  int cur_w = 0, cur_h = 0;
  glfwGetWindowSize(page.window, &cur_w, &cur_h);
  if (w != cur_w || h != cur_h) glfwSetWindowSize(page.window, w, h);
  if (ratio != page.pixel_ratio) {  // (zoomed, or moved to another screen)
    page.pixel_ratio = ratio;
    set_ui_scale(page, page.ui_scale);
  }
}

// The browser's own controls, under the panel's scene picker: share the link of what is shown,
// open a scene file, and the UI scale (the desktop's --ui-scale, which a link's ui-scale sets too).
void browser_controls(Page& page) {
  const bool copy = ImGui::Button(tr("Copy link"));
  page.copy_button = {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                      ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y};
  if (copy) {
    page.link =
        page_address() + "#" + link_of(*page.app, page.sets, page.ui_scale, page.homework_code);
    copy_to_clipboard(page.link);
    set_page_link(page.link);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  ui::same_line_if_fits(ImGui::CalcTextSize(tr("Open file...")).x + 2.0f * style.FramePadding.x);
  if (ImGui::Button(tr("Open file..."))) choose_scene_file();
  static constexpr double kScales[] = {0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0};
  char current[16];
  std::snprintf(current, sizeof current, tr("UI %g"), page.ui_scale);
  // (On the next line where the row has no room for it: a small laptop's panel cut it.)
  const float scale_width = ImGui::CalcTextSize(tr("UI 1.25")).x + ImGui::GetFrameHeight() * 1.6f;
  ui::same_line_if_fits(scale_width);
  ImGui::SetNextItemWidth(scale_width);
  if (ImGui::BeginCombo("##ui-scale", current)) {
    for (double s : kScales) {
      char item[16];
      std::snprintf(item, sizeof item, tr("UI %g"), s);
      if (ImGui::Selectable(item, s == page.ui_scale))
        page.next_ui_scale = s;  // (the fonts are in use now)
    }
    ImGui::EndCombo();
  }
  if (ImGui::Button(tr("Homework 8 in JavaScript..."))) open_homework_panel();
  page.homework_button = {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                          ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y};
  if (page.homework.has_code()) ui::draw_homework_status(page.homework_status);
  if (!page.link.empty()) {
    // What was copied, as text to see or to copy by hand.
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText("##link", page.link.data(), page.link.size() + 1,
                     ImGuiInputTextFlags_ReadOnly);
  }
}

// --- The frame -----------------------------------------------------------------------------

void frame() {
  Page& page = *g_page;
  if (!page.pacer.take()) return;
  fit_canvas(page);
  if (page.next_ui_scale) set_ui_scale(page, *std::exchange(page.next_ui_scale, std::nullopt));
  if (page.app->apply_language())
    ImGui_ImplOpenGL3_DestroyDeviceObjects();  // the font texture, remade
  FrameSize size;
  glfwGetFramebufferSize(page.window, &size.fb_width, &size.fb_height);
  glfwGetWindowSize(page.window, &size.win_width, &size.win_height);
  if (size.fb_width <= 0 || size.fb_height <= 0) return;
  const double start = emscripten_get_now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  page.homework.poll(page.app->session(), page.homework_status);
  page.app->frame(size);
  page.frame_ms = emscripten_get_now() - start;
  page.scene =
      ui::scene_viewport(page.app->ui(), page.app->session(), size.win_width, size.win_height);
  page.win_width = size.win_width;
  page.win_height = size.win_height;
  if (page.app->take_opened()) page.sets.clear();  // another scene, opened as its file says
  if (++page.frames == 1) {
    first_frame_shown();
    if (!page.homework_code.empty()) start_homework(page.homework_code);  // the link's code, run
  }
}

// The app for the page's link; a link that cannot be followed opens the default scene instead,
// with one message saying which parameter is wrong and what it allows.
std::unique_ptr<InteractiveApp> app_for_link(Page& page) {
  AppSettings settings;
  std::string problem;
  std::optional<Opened> opened;
  try {
    settings = settings_from_link(location_fragment());
    opened = open_settings(settings);
    if (settings.compare)
      make_scene_kind(opened->prepared.scene)->lanes_named(*settings.compare, "link: compare");
  } catch (const std::exception& e) {
    problem = e.what();
    settings = AppSettings();
    opened = open_settings(settings);
  }
  page.ui_scale = settings.ui_scale;
  page.sets = settings.sim.sets;
  page.homework_code = settings.homework_js;
  page.pixel_ratio = std::clamp(emscripten_get_device_pixel_ratio(), 0.5, 4.0);
  const float scale = static_cast<float>(page.ui_scale * page.pixel_ratio);
  // The link's language, else the browser's (before the fonts: they carry its glyphs).
  try {
    use_language(settings.language.empty() ? browser_language() : settings.language);
  } catch (const std::exception& e) {
    if (problem.empty()) problem = e.what();
  }
  ui::apply_theme(scale);
  // No multisampling: SwiftShader and many laptops' GPUs draw it slowly, and the lines and
  // spheres are drawn with their own smooth edges.
  auto app = std::make_unique<InteractiveApp>(std::move(opened->prepared), settings,
                                              std::move(opened->script), scale, 0, true);
  if (!problem.empty()) app->say(problem);
  app->set_platform_controls([&page] { browser_controls(page); });
  return app;
}

}  // namespace

}  // namespace springlab::app::web

// --- The functions the page calls ------------------------------------------------------------

extern "C" {

// A scene file's text from the page (file picker or drop): written where the desktop would read
// it and opened with the same loader and checks; a bad file leaves the scene running and says why.
EMSCRIPTEN_KEEPALIVE void springlab_open_scene_text(const char* file_name, const char* text) {
  using namespace springlab::app::web;
  if (!g_page) return;
  namespace fs = std::filesystem;
  std::string name = fs::path(file_name ? file_name : "").filename().string();
  if (name.empty()) name = "scene.json";  // not shown: a file's name
  const fs::path dir = "/user";           // not shown: a folder
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << (text ? text : "");
  g_page->app->open_after_frame(path.string());
}

// Homework 8: the student's JavaScript, compiled by the page (homework.js), checked here by the
// checker of `springlab homework check` and run as lanes beside springlab's rows: the report, as
// the command line prints it (in the app's language), and its count of failed checks, as JSON
// {"text", "failed"}. The checker's calls have 1 s each (and 0.05 ms a step); a lane's 0.25 s,
// so that an endless loop stops its lane, not the page, for long.
EMSCRIPTEN_KEEPALIVE const char* springlab_homework_check(const char* code) {
  using namespace springlab;
  using namespace springlab::app::web;
  static std::string text;
  if (!g_page || !js_code_ready()) return "{}";
  const double start = emscripten_get_now();
  JsRope checking(1000.0, 0.05);
  homework::Report report = homework::check_rope(checking);
  const double seconds = (emscripten_get_now() - start) / 1000.0;
  text = homework_result(report);
  g_page->homework_code = code ? code : "";
  g_page->homework_status.file = tr("your JavaScript");
  g_page->homework_status.error.clear();
  g_page->homework.set(std::move(report), seconds,
                       [] { return std::make_shared<JsRope>(250.0, 0.05); });
  return text.c_str();
}

// The panel's own words (homework.js), in the app's language, as JSON.
EMSCRIPTEN_KEEPALIVE const char* springlab_homework_words() {
  static std::string json;
  json = springlab::app::web::homework_words();
  return json.c_str();
}

// The student's code did not compile (the page says why): said in the app's panel too, while the
// last good code's lanes run on.
EMSCRIPTEN_KEEPALIVE void springlab_homework_failed(const char* message) {
  using namespace springlab::app::web;
  if (!g_page) return;
  g_page->homework_status.file = springlab::tr("your JavaScript");
  g_page->homework_status.error = message ? message : "";
}

// springlab in words (access.js, web/access.hpp): the app's state as JSON, and its controls.
EMSCRIPTEN_KEEPALIVE const char* springlab_describe() {
  static std::string json;
  if (!springlab::app::web::g_page) return "{}";
  json = springlab::app::web::describe(*springlab::app::web::g_page->app);
  return json.c_str();
}
EMSCRIPTEN_KEEPALIVE const char* springlab_chart_csv(int index) {
  using namespace springlab::app::web;
  static std::string csv;
  if (!g_page) return "";
  const auto shown = charts(*g_page->app);
  csv = index >= 0 && index < static_cast<int>(shown.size())
            ? springlab::chart::chart_csv(shown[index])
            : "";
  return csv.c_str();
}
EMSCRIPTEN_KEEPALIVE int springlab_control(const char* name, double value) {
  using namespace springlab::app::web;
  return g_page && name && control(*g_page->app, name, value) ? 1 : 0;
}
EMSCRIPTEN_KEEPALIVE int springlab_choose(const char* what, const char* name) {
  using namespace springlab::app::web;
  return g_page && what && name && choose(*g_page->app, what, name) ? 1 : 0;
}

// The UI scale from the page's script: the desktop's --ui-scale (0.5 to 4, times the pixel ratio).
EMSCRIPTEN_KEEPALIVE void springlab_set_ui_scale(double scale) {
  using namespace springlab::app::web;
  if (g_page && std::isfinite(scale)) g_page->next_ui_scale = scale;
}

// What is shown, as JSON, for the page's tests: scene, method (the row: an IK scene's solver), dt,
// lanes (their rows) and their times, the
// banner's message, the frame count.
EMSCRIPTEN_KEEPALIVE const char* springlab_status() {
  using namespace springlab;
  using namespace springlab::app::web;
  static std::string json;
  if (!g_page) return "{}";
  const app::Session& session = g_page->app->session();
  const auto quoted = [](const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
  };
  char number[256];
  json = "{\"scene\":" + quoted(g_page->app->scene_name());
  json +=
      ",\"method\":" +
      quoted(std::string(app::lane_row(session.primary()).name));  // (an IK scene's: its solver)
  std::snprintf(number, sizeof number, ",\"dt\":%.17g", session.primary().sim.settings().dt);
  json += number;
  std::snprintf(number, sizeof number, ",\"ks\":%.17g,\"kd\":%.17g", session.stiffness(),
                session.damping());
  json += number;
  std::snprintf(number, sizeof number, ",\"frames\":%ld,\"scale\":%.4g", g_page->frames,
                g_page->app->scale());
  json += number;
  const ui::FrameStats& stats = g_page->app->stats();
  std::snprintf(
      number, sizeof number,
      ",\"frame_ms\":%.4g,\"sim_ms\":%.4g,\"draw_ms\":%.4g,\"fps\":%.4g,\"realtime\":%.4g",
      g_page->frame_ms, stats.sim_ms, stats.draw_ms, stats.fps, stats.realtime);
  json += number;
  const ImVec4& b = g_page->copy_button;
  std::snprintf(number, sizeof number, ",\"copy_link\":[%g,%g,%g,%g]", b.x, b.y, b.z, b.w);
  json += number;
  const ImVec4& hb = g_page->homework_button;
  std::snprintf(number, sizeof number, ",\"homework_button\":[%g,%g,%g,%g]", hb.x, hb.y, hb.z,
                hb.w);
  json += number;
  const draw::Viewport& v = g_page->scene;
  std::snprintf(number, sizeof number, ",\"viewport\":[%d,%d,%d,%d]", v.x, v.y, v.width, v.height);
  json += number;
  json += ",\"paused\":" + std::string(session.paused() ? "true" : "false");
  json += ",\"lesson\":" + quoted(g_page->app->lesson() ? g_page->app->lesson()->name : "");
  std::snprintf(number, sizeof number, ",\"step\":%d,\"interrupted\":%s", g_page->app->step() + 1,
                g_page->app->interrupted() ? "true" : "false");
  json += number;
  json += ",\"message\":" + quoted(g_page->app->ui().message);
  json += ",\"lang\":" + quoted(current_language());
  const Camera& camera = g_page->app->ui().view.camera;  // how far the view is zoomed (a pinch)
  std::snprintf(number, sizeof number, ",\"zoom\":%.9g",
                camera.view == View::Planar ? camera.height : camera.distance);
  json += number;
  json += ",\"lanes\":[";
  for (std::size_t i = 0; i < session.lanes().size(); ++i) {
    const app::Lane& lane = session.lanes()[i];
    std::snprintf(
        number, sizeof number, "%s{\"method\":\"%s\",\"t\":%.17g,\"diverged\":%s,\"unstable\":%s",
        i ? "," : "", std::string(app::lane_row(lane).name).c_str(), lane.sim.state().t,
        lane.sim.diverged() ? "true" : "false", lane.sim.instability() ? "true" : "false");
    json += number;
    // A lane of one's own (homework): its label, and why it stopped where it did.
    if (!lane.own.empty()) json += ",\"own\":" + quoted(lane.own);
    if (lane.sim.divergence()) json += ",\"why\":" + quoted(lane.sim.divergence()->reason);
    json += "}";
  }
  json += "]}";
  return json.c_str();
}

// Where the last frame drew the scene and each panel, in CSS pixels from the canvas's top left, as
// JSON for the page's tests of layouts (index.html: window.springlabLayout()): {"scene":[x,y,w,h],
// "panels":[[x,y,w,h],...],"names":[...],"canvas":[w,h]}. The panels are Dear ImGui's windows shown
// in that frame, without child windows, tooltips and its implicit "Debug" window; the app lays
// them out in window pixels (the CSS box times the pixel ratio), divided back here.
EMSCRIPTEN_KEEPALIVE const char* springlab_layout() {
  using namespace springlab::app::web;
  static std::string json;
  if (!g_page || g_page->win_width <= 0 || g_page->win_height <= 0) return "{}";
  const Page& page = *g_page;
  const double sx = page.css_width / page.win_width, sy = page.css_height / page.win_height;
  char number[160];
  const auto rect = [&](double x, double y, double w, double h) {
    std::snprintf(number, sizeof number, "[%.6g,%.6g,%.6g,%.6g]", x * sx, y * sy, w * sx, h * sy);
    return std::string(number);
  };
  const springlab::draw::Viewport& v = page.scene;
  json = "{\"scene\":" + rect(v.x, v.y, v.width, v.height) + ",\"panels\":[";
  std::string names;
  for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    // (Between frames, Active is whether the last frame submitted the window.)
    if (!w->Active || w->Hidden || w->IsFallbackWindow ||
        (w->Flags & (ImGuiWindowFlags_ChildWindow | ImGuiWindowFlags_Tooltip)))
      continue;
    if (!names.empty()) json += ",";
    json += rect(w->Pos.x, w->Pos.y, w->Size.x, w->Size.y);
    names += names.empty() ? "\"" : ",\"";
    for (const char* c = w->Name; *c; ++c) {
      if (*c == '"' || *c == '\\') names += '\\';
      if (static_cast<unsigned char>(*c) >= 0x20) names += *c;
    }
    names += "\"";
  }
  std::snprintf(number, sizeof number, "],\"canvas\":[%.6g,%.6g]", page.css_width, page.css_height);
  json += number;
  json += ",\"names\":[" + names + "]}";
  return json.c_str();
}

}  // extern "C"

// --- main ----------------------------------------------------------------------------------

int main() {
  using namespace springlab::app::web;
  if (!glfwInit()) {
    std::fprintf(stderr, "springlab: GLFW could not start in this page\n");
    return 1;
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  static Page page;
  // not shown: a canvas has no title
  page.window = glfwCreateWindow(1280, 720, "springlab", nullptr, nullptr);
  if (!page.window) {
    std::fprintf(stderr, "springlab: this browser gives no WebGL2 context\n");
    return 1;
  }
  glfwMakeContextCurrent(page.window);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // nothing to save between visits
  io.LogFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(page.window, true);
  ImGui_ImplOpenGL3_Init("#version 300 es");

  page.app = app_for_link(page);
  g_page = &page;
  // The page's animation frames drive the loop; main returns and the page keeps running.
  emscripten_set_main_loop(frame, 0, false);
  return 0;
}
