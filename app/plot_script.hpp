// Figures are drawn by matplotlib scripts (scripts/*.py), as the field's reports are, not by the program itself: the
// bench's from its CSV files, a shot margin's from its JSON.
#pragma once
#include <string>
#include <vector>

namespace shotlab {

// Runs scripts/SCRIPT (under data_root()) with `args` and the first Python that has matplotlib: $SHOTLAB_PYTHON if
// set, else python3 on PATH, else /usr/bin/python3. Without one, or without the script, says in one line (as
// `command`) how to draw the figure later and returns true (the data files are the results); false when the script
// fails.
bool run_plot_script(const std::string& script, const std::vector<std::string>& args, const std::string& command);

// The bench's figures: scripts/bench_plots.py on out_dir.
bool draw_figures(const std::string& out_dir);

}  // namespace shotlab
