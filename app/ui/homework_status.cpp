#include "ui/homework_status.hpp"

#include <imgui.h>

#include "springlab/text.hpp"

namespace springlab::ui {

void draw_homework_status(const HomeworkStatus& status) {
  ImGui::Separator();
  ImGui::TextUnformatted(format_text(tr("Homework 8: %s"), status.file.c_str()).c_str());
  if (status.building) ImGui::TextDisabled("%s", tr("building the saved file..."));
  for (const std::string& line : status.lines) ImGui::TextWrapped("%s", line.c_str());
  if (!status.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
    ImGui::TextWrapped(
        "%s", format_text(tr("the saved file does not build (the last good build runs): %s"),
                          status.error.c_str())
                  .c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace springlab::ui
