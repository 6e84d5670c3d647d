"""What the benchmark scripts share: the line a report starts with (the CPU, the vCPUs and the commit measured), and
how a report is printed and written."""
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


def publish(lines, out=None):
    """Prints the report's lines and, given a path, writes them there too."""
    text = "\n".join(lines) + "\n"
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text)
