"""The line a benchmark report starts with: the CPU, the vCPUs and the commit it measured."""
import os
import platform
import subprocess


def describe(root):
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            model = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    return f"{model}, {os.cpu_count()} vCPUs, {platform.system()} {platform.release()}; commit {commit}"
