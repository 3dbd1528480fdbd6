#include "ui/lesson_band.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <numeric>

#include "chart/text_wrap.hpp"
#include "springlab/text.hpp"
#include "ui/theme.hpp"

namespace springlab::ui {

namespace {
constexpr float kBandPad = 12.0f, kBar = 8.0f, kGap = 6.0f;
const ImVec4 kPrompt(0.55f, 0.85f, 1.0f, 1.0f), kTookOver(1.0f, 0.75f, 0.2f, 1.0f);
}  // namespace

float lesson_band_height(float scale, int caption_lines, int title_rows, int prompt_lines,
                         bool narrow) {
  const float row = kFontSize + 8.0f;  // a framed row (buttons)
  const float caption =
      std::max(2, caption_lines) * kFontSize * (narrow ? 1.0f : kCaptionScale) * 1.17f;  // its font
  const float prompt = kFontSize * 1.25f * std::max(1, prompt_lines);
  return (2 * kBandPad + std::max(1, title_rows) * (row + kGap) + caption + prompt + kBar +
          2 * kGap) *
         scale;
}

namespace {
// The caption as drawn: in its font, wrapped at spaces to the band's inner width.
// A phone's width (under 600 units): the caption in the panels' font, so that the scene and a
// chart keep their room under it.
bool narrow_band(float width, float scale) {
  return width < 600.0f * scale;
}
int caption_font(float width, float scale) {
  return narrow_band(width, scale) ? kPanelFont : kCaptionFont;
}

std::string caption_text(const std::string& caption, float width, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.Fonts->Fonts.Size <= kCaptionFont) return caption;
  const ImFont* font = io.Fonts->Fonts[caption_font(width, scale)];
  if (!font->IsLoaded()) return caption;  // the atlas not built yet: no glyphs to measure
  return wrap_text(caption, font, font->FontSize * font->Scale, width - 2 * kBandPad * scale);
}
}  // namespace

namespace {

// "Lesson 3 of 12 · Explicit Euler gains energy — step 1 of 1: Energy grows at every step".
std::string title_text(const LessonBand& band) {
  const int steps = static_cast<int>(band.durations.size());
  return (band.number > 0 ? format_text(tr("Lesson %d of %d"), band.number, band.count)
                          : std::string(tr("Lesson"))) +
         "  \u00b7  " + band.title + "   \u2014   " +
         format_text(tr("step %d of %d: %s"), band.step + 1, steps, band.step_title.c_str());
}

// The title row: the title wrapped beside the buttons (Back, Next, End lesson), or, in a narrow
// window, the buttons on a row of their own above it and the title wrapped to the whole width.
struct TitleRows {
  std::string title;  // with its line breaks
  bool buttons_above = false;
  float buttons_width = 0.0f;
  int rows() const {
    return 1 + static_cast<int>(std::count(title.begin(), title.end(), '\n')) +
           (buttons_above ? 1 : 0);
  }
};

const char* next_label(const LessonBand& band) {
  const bool at_end = band.step + 1 >= static_cast<int>(band.durations.size());
  return !at_end ? tr("Next \u2192") : band.last_lesson ? tr("Done") : tr("Next lesson \u2192");
}

TitleRows title_rows(const LessonBand& band, float width, float scale) {
  TitleRows out;
  out.title = title_text(band);
  const ImGuiIO& io = ImGui::GetIO();
  if (io.Fonts->Fonts.Size <= kPanelFont || !io.Fonts->Fonts[kPanelFont]->IsLoaded()) return out;
  const ImFont* font = io.Fonts->Fonts[kPanelFont];
  const float size = font->FontSize * font->Scale;
  const auto text_w = [&](const char* t) { return font->CalcTextSizeA(size, FLT_MAX, 0.0f, t).x; };
  const float inner = width - 2 * kBandPad * scale, spacing = 8.0f * scale,
              frame = ImGui::GetStyle().FramePadding.x;
  if (band.interactive)
    out.buttons_width = text_w(tr("\u2190 Back")) + text_w(next_label(band)) +
                        text_w(tr("End lesson")) + 6 * frame + 2 * spacing;
  const float beside = inner - (band.interactive ? out.buttons_width + spacing : 0.0f);
  out.buttons_above =
      band.interactive && (beside < 0.5f * inner || text_w(out.title.c_str()) > beside);
  const float room = out.buttons_above || !band.interactive ? inner : beside;
  if (text_w(out.title.c_str()) > room)
    out.title = wrap_text(out.title, font, size, room);  // (one line: as written)
  return out;
}

// The progress bar on the band's foot: one segment a step, as long as its duration (a step's
// segment from x0 + (start / total)(x1 - x0), with a 2 px gap before it), filled up to now: the
// steps before whole, the current one by elapsed / its duration.
void draw_band_progress(const LessonBand& band, float width, float height, float scale) {
  const int steps = static_cast<int>(band.durations.size());
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float x0 = kBandPad * scale, x1 = width - kBandPad * scale, y1 = height - kBandPad * scale,
              y0 = y1 - kBar * scale;
  const double total =
      std::max(1e-9, std::accumulate(band.durations.begin(), band.durations.end(), 0.0));
  double start = 0.0;
  for (int k = 0; k < steps; ++k) {
    const float a =
        x0 + static_cast<float>(start / total) * (x1 - x0) + (k > 0 ? 2.0f * scale : 0.0f);
    const float b = x0 + static_cast<float>((start + band.durations[k]) / total) * (x1 - x0);
    const double filled = k < band.step   ? 1.0
                          : k > band.step ? 0.0
                                          : std::clamp(band.elapsed / band.durations[k], 0.0, 1.0);
    dl->AddRectFilled(ImVec2(a, y0), ImVec2(b, y1), IM_COL32(60, 66, 76, 255), 2.0f);
    if (filled > 0.0)
      dl->AddRectFilled(ImVec2(a, y0), ImVec2(a + static_cast<float>(filled) * (b - a), y1),
                        k == band.step ? IM_COL32(90, 175, 255, 255) : IM_COL32(70, 130, 200, 255),
                        2.0f);
    start += band.durations[k];
  }
}

}  // namespace

// "Try this: ..." wrapped to the band's width (one line at 1280 x 720; more on a phone).
std::string prompt_text(const LessonBand& band, float width, float scale) {
  std::string text = format_text(tr("Try this: %s"), band.prompt.c_str());
  const ImGuiIO& io = ImGui::GetIO();
  if (band.prompt.empty() || io.Fonts->Fonts.Size <= kPanelFont ||
      !io.Fonts->Fonts[kPanelFont]->IsLoaded())
    return text;
  const ImFont* font = io.Fonts->Fonts[kPanelFont];
  return wrap_text(text, font, font->FontSize * font->Scale, width - 2 * kBandPad * scale);
}

float lesson_band_height(const LessonBand& band, float width, float scale) {
  const auto lines = [](const std::string& t) {
    return 1 + static_cast<int>(std::count(t.begin(), t.end(), '\n'));
  };
  return lesson_band_height(scale, lines(caption_text(band.caption, width, scale)),
                            title_rows(band, width, scale).rows(),
                            lines(prompt_text(band, width, scale)), narrow_band(width, scale));
}

BandRequests draw_lesson_band(const LessonBand& band, float width, float scale) {
  BandRequests out;
  const float height = lesson_band_height(band, width, scale);
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kBandPad * scale, kBandPad * scale));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(8.0f * scale, kGap * scale));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.03f, 0.04f, 0.05f, 0.97f));
  ImGui::Begin("##lesson", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoNav);

  // Where we are, and the way on: the buttons beside the title, or above it in a narrow window.
  const TitleRows title = title_rows(band, width, scale);
  const auto buttons = [&] {
    const char* next = next_label(band);
    ImGui::BeginDisabled(band.step == 0);
    out.back = ImGui::Button(tr("\u2190 Back"));
    ImGui::EndDisabled();
    ImGui::SameLine();
    out.next = ImGui::Button(next);
    ImGui::SameLine();
    out.end = ImGui::Button(tr("End lesson"));
  };
  if (title.buttons_above) {
    ImGui::SetCursorPosX(
        std::max(ImGui::GetCursorPosX(), width - kBandPad * scale - title.buttons_width));
    buttons();
  }
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("%s", title.title.c_str());
  if (band.interactive && !title.buttons_above) {
    ImGui::SameLine(
        std::max(ImGui::GetCursorPosX(), width - kBandPad * scale - title.buttons_width));
    buttons();
  }

  // The caption, large.
  ImGuiIO& io = ImGui::GetIO();
  const bool caption_font = io.Fonts->Fonts.Size > kCaptionFont;
  if (caption_font) ImGui::PushFont(io.Fonts->Fonts[ui::caption_font(width, scale)]);
  ImGui::TextUnformatted(caption_text(band.caption, width, scale).c_str());
  if (caption_font) ImGui::PopFont();

  // What the class may try, or the way back once it has taken over; on the band's last row.
  const std::string prompt = prompt_text(band, width, scale);
  const int prompt_lines = 1 + static_cast<int>(std::count(prompt.begin(), prompt.end(), '\n'));
  ImGui::SetCursorPosY(height - kBandPad * scale - kBar * scale - kGap * scale -
                       kFontSize * 1.25f * scale * prompt_lines);
  if (band.interrupted && band.interactive) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextColored(kTookOver, tr("You took over: the lesson waits."));
    ImGui::SameLine();
    out.resume = ImGui::SmallButton(tr("Resume the lesson (this step from its start)"));
  } else if (!band.prompt.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kPrompt);
    ImGui::TextUnformatted(prompt.c_str());
    ImGui::PopStyleColor();
  }

  draw_band_progress(band, width, height, scale);
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
