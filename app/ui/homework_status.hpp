// Homework 8 in the app's panels: the student's file, what its last build said and which method
// each of its steps was found to be (filled by app/homework/homework_watch on the desktop).
#pragma once

#include <string>
#include <vector>

namespace springlab::ui {

struct HomeworkStatus {
  std::string file;
  std::vector<std::string> lines;
  std::string error;  // the last build's compiler error, while the last good build runs
  bool building = false;
};

// Drawn in the panels (under the scene picker).
void draw_homework_status(const HomeworkStatus& status);

}  // namespace springlab::ui
