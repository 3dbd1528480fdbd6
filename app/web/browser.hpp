// What the app asks of the page it runs in (JavaScript, app/web/index.html): its link, the
// clipboard, the file picker, and word that the first frame is up.
#pragma once

#include <string>

namespace springlab::app::web {

std::string location_fragment();  // "#scene=rope&..." or ""
std::string page_address();       // the page's address without its fragment
std::string browser_language();   // navigator.language: "zh-CN", "en-GB", ...
void copy_to_clipboard(const std::string& text);
void choose_scene_file();  // opens the page's file picker; the file comes back through
                           // springlab_open_scene_text
void first_frame_shown();  // the page hides its progress line
void set_page_link(const std::string& link);
void open_homework_panel();  // Homework 8's code panel (homework.js)
void start_homework(
    const std::string& code);  // the panel opened with this code, which is run  // shown to the
                               // page (and to its tests) as window.springlabLink

}  // namespace springlab::app::web
