"""A finished run's folder as scripts/encoder_transient_calibration and
scripts/stop_displacement_calibration read it: robot.nominal and odometry.ekf of its config.yaml,
the truth poses of trajectory.csv and the ticks of encoders.csv. A folder that is not a finished
run (a sweep's, one still running or killed: no complete.json), a missing python3-yaml, an absent
key or column, or a value that is no number is one line naming the file and the field, exit 2;
each was a Python traceback, and a run killed half way was calibrated on its first half (s66).
"""
import csv
import math
import os
import sys

BAD_INPUT = 2


def fail(script, text):
    print(f"{script}: {text}", file=sys.stderr)
    sys.exit(BAD_INPUT)


def number(script, path, where, text, whole=False):
    try:
        v = math.nan if isinstance(text, bool) else int(text) if whole else float(text)
    except (TypeError, ValueError):
        v = math.nan
    if not math.isfinite(v):
        kind = "a whole number" if whole else "a number"
        fail(script, f"{path}: {where}: expected {kind}, got '{text}'")
    return v


def rows(script, path, columns):
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames is None:
                fail(script, f"{path}: empty file (no header line)")
            for column in columns:
                if column not in reader.fieldnames:
                    fail(script, f"{path}: no column '{column}'")
            return [(reader.line_num, row) for row in reader]
    except FileNotFoundError:
        fail(script, f"{path}: no such file")
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        fail(script, f"{path}: cannot read: {getattr(error, 'strerror', None) or error}")


def read_run(script, run_dir):
    """(nominal wheel_radius_m, track_m, encoder_ticks_per_rev, wheel_diameter_ratio_prior,
    track_ratio_prior, truth {time: (x, y, theta)}, encoder [(time, left, right)]) of a run."""
    try:
        import yaml
    except ImportError:
        fail(script, "needs python3-yaml (Debian: apt-get install python3-yaml; scripts/setup "
             "installs it)")
    if not os.path.isdir(run_dir):
        fail(script, f"{run_dir}: {'not a folder' if os.path.exists(run_dir) else 'no such folder'}"
             " (give the folder of a finished plywood run)")
    if not os.path.isfile(os.path.join(run_dir, "complete.json")):
        fail(script, f"{run_dir}: not a finished run: no complete.json (a run still running or "
             "killed, or a folder of runs: give one run's folder)")
    config_path = os.path.join(run_dir, "config.yaml")
    try:
        with open(config_path, encoding="utf-8") as f:
            config = yaml.safe_load(f)
    except FileNotFoundError:
        fail(script, f"{config_path}: no such file")
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as error:
        fail(script, f"{config_path}: cannot read: {getattr(error, 'strerror', None) or error}")
    robot = config.get("robot") if isinstance(config, dict) else None
    nominal = robot.get("nominal") if isinstance(robot, dict) else None
    if not isinstance(nominal, dict):
        fail(script, f"{config_path}: robot.nominal: absent")
    geometry = []
    for key in ("wheel_radius_m", "track_m", "encoder_ticks_per_rev"):
        v = number(script, config_path, f"robot.nominal.{key}", nominal.get(key))
        if v <= 0:
            fail(script, f"{config_path}: robot.nominal.{key}: expected > 0, got {v}")
        geometry.append(v)
    ekf = config.get("odometry") or {}
    ekf = (ekf.get("ekf") if isinstance(ekf, dict) else None) or {}
    if not isinstance(ekf, dict):
        fail(script, f"{config_path}: odometry.ekf: expected a mapping")
    priors = [number(script, config_path, f"odometry.ekf.{key}", ekf.get(key, 1.0))
              for key in ("wheel_diameter_ratio_prior", "track_ratio_prior")]
    path = os.path.join(run_dir, "trajectory.csv")
    truth = {}
    for line, row in rows(script, path, ("time_s", "truth_x_m", "truth_y_m", "truth_theta_rad")):
        truth[round(number(script, path, f"line {line}: time_s", row["time_s"]), 6)] = tuple(
            number(script, path, f"line {line}: {c}", row[c])
            for c in ("truth_x_m", "truth_y_m", "truth_theta_rad"))
    path = os.path.join(run_dir, "encoders.csv")
    encoder = []
    for line, row in rows(script, path, ("time_s", "left_ticks", "right_ticks")):
        t = round(number(script, path, f"line {line}: time_s", row["time_s"]), 6)
        if encoder and t <= encoder[-1][0]:
            # Two samples of one time divided a tick count by zero (s66).
            fail(script, f"{path}: line {line}: time_s: {row['time_s']} is not after the line "
                 "before's")
        ticks = (number(script, path, f"line {line}: {c}", row[c], True)
                 for c in ("left_ticks", "right_ticks"))
        encoder.append((t, *ticks))
    return (*geometry, *priors, truth, encoder)
