#include "web/browser.hpp"

#include <emscripten.h>

#include <cstdlib>
#include <memory>

namespace {

// JavaScript, kept as written (clang-format would write `=>` as `= >`).
// clang-format off
// A JavaScript string handed to C++: malloc'ed UTF-8 that the caller frees.
EM_JS(char*, js_location_fragment, (), {
  const text = window.location.hash || "";
  const size = lengthBytesUTF8(text) + 1;
  const p = _malloc(size);
  stringToUTF8(text, p, size);
  return p;
});

EM_JS(char*, js_browser_language, (), {
  const text = navigator.language || "en";
  const size = lengthBytesUTF8(text) + 1;
  const p = _malloc(size);
  stringToUTF8(text, p, size);
  return p;
});

EM_JS(char*, js_page_address, (), {
  const text = window.location.origin + window.location.pathname;
  const size = lengthBytesUTF8(text) + 1;
  const p = _malloc(size);
  stringToUTF8(text, p, size);
  return p;
});

// The asynchronous clipboard needs a secure page and permission; where it fails, the older
// select-and-copy of a hidden text field. Neither leaves an error in the console.
EM_JS(void, js_copy_to_clipboard, (const char* text), {
  const value = UTF8ToString(text);
  const fallback = () => {
    const field = document.createElement("textarea");
    field.value = value;
    document.body.appendChild(field);
    field.select();
    try { document.execCommand("copy"); } catch (e) {}
    field.remove();
  };
  if (navigator.clipboard && window.isSecureContext) navigator.clipboard.writeText(value).catch(fallback);
  else fallback();
});

EM_JS(void, js_choose_scene_file, (), {
  const input = document.getElementById("scene-file");
  if (input) input.click();
});

EM_JS(void, js_first_frame_shown, (), {
  if (typeof window.springlabFirstFrame === "function") window.springlabFirstFrame();
});

EM_JS(void, js_set_page_link, (const char* text), { window.springlabLink = UTF8ToString(text); });

EM_JS(void, js_open_homework_panel, (), {
  if (window.springlabHomework && window.springlabHomework.open) window.springlabHomework.open();
});

EM_JS(void, js_start_homework, (const char* code), {
  if (window.springlabHomework && window.springlabHomework.start) window.springlabHomework.start(UTF8ToString(code));
});
// clang-format on

std::string taken(char* p) {
  std::unique_ptr<char, decltype(&std::free)> owned(p, &std::free);
  return p ? std::string(p) : std::string();
}

}  // namespace

namespace springlab::app::web {

std::string location_fragment() {
  return taken(js_location_fragment());
}
std::string page_address() {
  return taken(js_page_address());
}
std::string browser_language() {
  return taken(js_browser_language());
}
void copy_to_clipboard(const std::string& text) {
  js_copy_to_clipboard(text.c_str());
}
void choose_scene_file() {
  js_choose_scene_file();
}
void first_frame_shown() {
  js_first_frame_shown();
}
void set_page_link(const std::string& link) {
  js_set_page_link(link.c_str());
}
void open_homework_panel() {
  js_open_homework_panel();
}
void start_homework(const std::string& code) {
  js_start_homework(code.c_str());
}

}  // namespace springlab::app::web
