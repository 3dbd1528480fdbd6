#include "ui/lesson_band.hpp"

#include <imgui.h>

#include <algorithm>
#include <numeric>

#include "ui/text_wrap.hpp"
#include "ui/theme.hpp"
#include "springlab/text.hpp"

namespace springlab::ui {

namespace {
constexpr float kPad = 12.0f, kBar = 8.0f, kGap = 6.0f;
const ImVec4 kPrompt(0.55f, 0.85f, 1.0f, 1.0f), kTookOver(1.0f, 0.75f, 0.2f, 1.0f);
}  // namespace

float lesson_band_height(float scale, int caption_lines) {
  const float row = kFontSize + 8.0f;                                         // a framed row (buttons)
  const float caption = std::max(2, caption_lines) * kFontSize * kCaptionScale * 1.17f;  // the caption's font
  const float prompt = kFontSize * 1.25f;
  return (2 * kPad + row + caption + prompt + kBar + 3 * kGap) * scale;
}

namespace {
// The caption as drawn: in its font, wrapped at spaces to the band's inner width.
std::string caption_text(const std::string& caption, float width, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.Fonts->Fonts.Size <= kCaptionFont) return caption;
  const ImFont* font = io.Fonts->Fonts[kCaptionFont];
  if (!font->IsLoaded()) return caption;  // the atlas not built yet: no glyphs to measure
  return wrap_text(caption, font, font->FontSize * font->Scale, width - 2 * kPad * scale);
}
}  // namespace

float lesson_band_height(const LessonBand& band, float width, float scale) {
  const std::string caption = caption_text(band.caption, width, scale);
  return lesson_band_height(scale, 1 + static_cast<int>(std::count(caption.begin(), caption.end(), '\n')));
}

BandRequests draw_lesson_band(const LessonBand& band, float width, float scale) {
  BandRequests out;
  const float height = lesson_band_height(band, width, scale);
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kPad * scale, kPad * scale));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(8.0f * scale, kGap * scale));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.03f, 0.04f, 0.05f, 0.97f));
  ImGui::Begin("##lesson", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoNav);

  // Where we are, and the way on.
  const int steps = static_cast<int>(band.durations.size());
  const std::string where =
      (band.number > 0 ? format_text(tr("Lesson %d of %d"), band.number, band.count) : std::string(tr("Lesson"))) +
      "  \u00b7  " + band.title + "   \u2014   " +
      format_text(tr("step %d of %d: %s"), band.step + 1, steps, band.step_title.c_str());
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("%s", where.c_str());
  if (band.interactive) {
    const bool at_end = band.step + 1 >= steps;
    const char* next = !at_end ? tr("Next \u2192") : band.last_lesson ? tr("Done") : tr("Next lesson \u2192");
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttons = ImGui::CalcTextSize(tr("\u2190 Back")).x + ImGui::CalcTextSize(next).x +
                          ImGui::CalcTextSize(tr("End lesson")).x + 6 * style.FramePadding.x + 2 * style.ItemSpacing.x;
    ImGui::SameLine(std::max(ImGui::GetCursorPosX(), width - kPad * scale - buttons));
    ImGui::BeginDisabled(band.step == 0);
    out.back = ImGui::Button(tr("\u2190 Back"));
    ImGui::EndDisabled();
    ImGui::SameLine();
    out.next = ImGui::Button(next);
    ImGui::SameLine();
    out.end = ImGui::Button(tr("End lesson"));
  }

  // The caption, large.
  ImGuiIO& io = ImGui::GetIO();
  const bool caption_font = io.Fonts->Fonts.Size > kCaptionFont;
  if (caption_font) ImGui::PushFont(io.Fonts->Fonts[kCaptionFont]);
  ImGui::TextUnformatted(caption_text(band.caption, width, scale).c_str());
  if (caption_font) ImGui::PopFont();

  // What the class may try, or the way back once it has taken over; on the band's last row.
  ImGui::SetCursorPosY(height - kPad * scale - kBar * scale - kGap * scale - kFontSize * 1.25f * scale);
  if (band.interrupted && band.interactive) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextColored(kTookOver, tr("You took over: the lesson waits."));
    ImGui::SameLine();
    out.resume = ImGui::SmallButton(tr("Resume the lesson (this step from its start)"));
  } else if (!band.prompt.empty()) {
    ImGui::TextColored(kPrompt, tr("Try this: %s"), band.prompt.c_str());
  }

  // Progress: one segment a step, as long as its duration, filled up to now.
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float x0 = kPad * scale, x1 = width - kPad * scale, y1 = height - kPad * scale, y0 = y1 - kBar * scale;
  const double total = std::max(1e-9, std::accumulate(band.durations.begin(), band.durations.end(), 0.0));
  double start = 0.0;
  for (int k = 0; k < steps; ++k) {
    const float a = x0 + static_cast<float>(start / total) * (x1 - x0) + (k > 0 ? 2.0f * scale : 0.0f);
    const float b = x0 + static_cast<float>((start + band.durations[k]) / total) * (x1 - x0);
    const double filled = k < band.step ? 1.0 : k > band.step ? 0.0 : std::clamp(band.elapsed / band.durations[k], 0.0, 1.0);
    dl->AddRectFilled(ImVec2(a, y0), ImVec2(b, y1), IM_COL32(60, 66, 76, 255), 2.0f);
    if (filled > 0.0)
      dl->AddRectFilled(ImVec2(a, y0), ImVec2(a + static_cast<float>(filled) * (b - a), y1),
                        k == band.step ? IM_COL32(90, 175, 255, 255) : IM_COL32(70, 130, 200, 255), 2.0f);
    start += band.durations[k];
  }
  ImGui::End();
  ImGui::PopStyleColor();
  ImGui::PopStyleVar(2);
  return out;
}

LessonBand band_of(const Lesson& lesson, int k, int number, int count) {
  LessonBand b;
  b.number = number;
  b.count = count;
  b.last_lesson = number == 0 || number >= count;
  b.title = tr(lesson.title);
  b.step = k;
  for (const LessonStep& s : lesson.steps) b.durations.push_back(s.duration);
  const LessonStep& step = lesson.steps[k];
  b.step_title = tr(step.title);
  b.caption = tr(step.caption);
  b.prompt = tr(step.prompt);
  return b;
}

void show_step(UiState& ui, ComparePanel& accuracy, const Lesson& lesson, int k) {
  const LessonStep& step = lesson.steps[k];
  ui.lesson = lesson.name;
  ui.band = lesson_band_height(ui.scale);
  ui.lesson_charts = step.charts;
  ui.region = step.region;
  ui.view.mode = step.mode;
  ui.accuracy = accuracy.open = step.accuracy;
  if (!step.accuracy) return;
  accuracy.methods = {};
  for (const LessonClaim& c : step.claims)
    for (const auto& [name, order] : c.orders) accuracy.methods.set(*find_method(name), true);
  accuracy.chart = 1;  // error against work
}

}  // namespace springlab::ui
