// The bench's figures are drawn from its CSV files by scripts/bench_plots.py (python3 + matplotlib), as the field's
// reports are, not by the bench itself.
#pragma once
#include <string>

namespace shotlab {

// Runs scripts/bench_plots.py (under data_root()) on out_dir with the first Python that has matplotlib:
// $SHOTLAB_PYTHON if set, else python3 on PATH, else /usr/bin/python3. Without one, or without the script, says in
// one line how to draw the figures and returns true (the CSV files are the results); false when the script fails.
bool draw_figures(const std::string& out_dir);

}  // namespace shotlab
