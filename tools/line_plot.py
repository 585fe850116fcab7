# SPDX-License-Identifier: MIT
"""Line plots through gnuplot for the measuring scripts (tools/sweep/sweep.py,
tools/reference/quality_curve.py): each series a list of (x, y) points, written as a data file
beside the PNG. gnuplot is optional (apt-get install gnuplot-nox); without it nothing is drawn
and the caller's CSV has everything. Python's standard library only."""
import os
import shutil
import subprocess


def gnuplot_found(script_name):
    """Whether gnuplot is installed; says what is missing, as `script_name`, when it is not."""
    if shutil.which("gnuplot"):
        return True
    print(f"{script_name}: gnuplot not found (apt-get install gnuplot-nox): no plot, the CSV has everything")
    return False


def line_plot(png, title, xlabel, ylabel, series, logscale="x", size=(1000, 620)):
    """Draws `series` ([(label, [(x, y), ...]), ...]) into `png`; series without points are left out."""
    out_dir = os.path.dirname(png)
    stem = os.path.splitext(os.path.basename(png))[0]
    plots = []
    for index, (label, points) in enumerate(series):
        if not points:
            continue
        data = os.path.join(out_dir, f"{stem}_{index}.dat")
        with open(data, "w") as f:
            f.writelines(f"{x} {y}\n" for x, y in points)
        plots.append(f"'{data}' with linespoints title '{label}'")
    if not plots:
        return
    script = "\n".join([
        f"set terminal pngcairo size {size[0]},{size[1]} noenhanced",
        f"set output '{png}'",
        f"set title '{title}'",
        f"set xlabel '{xlabel}'", f"set ylabel '{ylabel}'",
        f"set logscale {logscale}", "set grid", "set key left top",
        "plot " + ", ".join(plots),
    ])
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
