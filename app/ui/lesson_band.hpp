// The lesson's band across the top of the window: which lesson and step, the caption (large, in
// its own font, never over the scene: the scene's viewport starts below the band), the class's
// "try this" prompt, and a progress bar with one segment a step. In the app it has back, next and
// end buttons, and, once the class has taken over (a drag, a slider), a way back into the lesson;
// burned into a video it has none.
#pragma once

#include <string>
#include <vector>

#include "springlab/lesson.hpp"
#include "ui/compare_panel.hpp"
#include "ui/panels.hpp"

namespace springlab::ui {

struct LessonBand {
  int number = 0, count = 0;  // the lesson's place in the course (0: a lesson file of one's own)
  std::string title;
  int step = 0;                   // from 0
  std::vector<double> durations;  // s, every step's
  std::string step_title, caption, prompt;
  double elapsed =
      0.0;  // s into the step: simulated time over the step's speed (paused, it stands still)
  bool interrupted = false;
  bool interactive = true;  // buttons (the app) or none (a video)
  bool last_lesson = true;  // no next lesson after this one
};

struct BandRequests {
  bool back = false, next = false, resume = false, end = false;
};

// The band's height at `scale`, in window units: a title row, the caption's lines (two at least,
// so that the scene keeps its place from step to step; core/include/springlab/lesson.hpp limits a
// caption to two at 1280 x 720), the prompt and the progress bar.
float lesson_band_height(
    float scale, int caption_lines = 2, int title_rows = 1, int prompt_lines = 1,
    bool narrow = false);  // narrow: a phone's, the caption in the panels' font

// The height of `band` across a window `width` wide: a narrower window (a laptop's browser) wraps
// the caption onto more lines, and the band grows to hold them rather than cut them off.
float lesson_band_height(const LessonBand& band, float width, float scale);

BandRequests draw_lesson_band(const LessonBand& band, float width, float scale);

// The band of step `step` (from 0) of a lesson, `number` of `count` in the course (elapsed and
// interrupted are the caller's to set).
LessonBand band_of(const Lesson& lesson, int step, int number, int count);

// What a step shows, set in the panels' state: the band's room, its charts, the stability region,
// the limiting mode, and the accuracy panel (open or not; its methods those an `orders` claim
// names, none: every method; error against work, the same on every machine). Starting the
// accuracy sweep is the caller's.
void show_step(UiState& ui, ComparePanel& accuracy, const Lesson& lesson, int step);

}  // namespace springlab::ui
