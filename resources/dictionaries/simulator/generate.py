#!/usr/bin/env python3
"""Writes the simulator dictionaries (servo-can.json, servo-modbus.json here) from the
family dictionaries one folder up: the same parameters, with the DriveDesk simulator's own
loop-gain parameters named and given ranges, and the "tuning" group naming their roles.

The gains are the simulator's model (docs/tuning.md); the protocol documents name no gain
parameter, so the family dictionaries (used with real drives) stay as they are.
Run it after changing a family dictionary or sim/<family>'s loopGainParameters()."""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))

ROLES = {
    "speed-kp": ({"en": "Speed-loop gain (simulator)", "zh": "速度环增益（模拟器）"}, "Hz",
                 {"en": "DriveDesk simulator's model: the speed loop's bandwidth. Higher is stiffer and faster; too high rings. Not a real drive's parameter.",
                  "zh": "DriveDesk 模拟器的模型：速度环带宽。越高越硬、越快；过高会振荡。并非真实驱动器的参数。"}),
    "speed-ki": ({"en": "Speed-loop integral gain (simulator)", "zh": "速度环积分增益（模拟器）"}, "1/s",
                 {"en": "DriveDesk simulator's model: removes the steady-state speed error; more overshoots. Not a real drive's parameter.",
                  "zh": "DriveDesk 模拟器的模型：消除速度稳态误差；过大会超调。并非真实驱动器的参数。"}),
    "position-kp": ({"en": "Position-loop gain (simulator)", "zh": "位置环增益（模拟器）"}, "1/s",
                    {"en": "DriveDesk simulator's model: speed command per count of following error. Not a real drive's parameter.",
                     "zh": "DriveDesk 模拟器的模型：每个脉冲跟随误差对应的速度指令。并非真实驱动器的参数。"}),
    "speed-feedforward": ({"en": "Speed feed-forward (simulator)", "zh": "速度前馈（模拟器）"}, "%",
                          {"en": "DriveDesk simulator's model: share of the profile's speed fed past the position loop. Not a real drive's parameter.",
                           "zh": "DriveDesk 模拟器的模型：越过位置环直接送入速度环的速度比例。并非真实驱动器的参数。"}),
    "torque-feedforward": ({"en": "Torque feed-forward (simulator)", "zh": "转矩前馈（模拟器）"}, "%",
                           {"en": "DriveDesk simulator's model: share of the torque the profile's acceleration needs, fed past the speed loop. Set 0 to see the speed loop alone in a step test. Not a real drive's parameter.",
                            "zh": "DriveDesk 模拟器的模型：按曲线加速度所需转矩直接前馈的比例。阶跃测试中设为 0 可单独观察速度环。并非真实驱动器的参数。"}),
    "acceleration": ({"en": "Acceleration (simulator)", "zh": "加速度（模拟器）"}, "r/min/ms",
                     {"en": "DriveDesk simulator's model: the acceleration and deceleration of its speed and move profiles. Not a real drive's parameter.",
                      "zh": "DriveDesk 模拟器的模型：速度与定位曲线的加减速度。并非真实驱动器的参数。"}),
}

# Keep in step with sim/servocan/simservocandrive.cpp and sim/servomodbus/simservomodbusdrive.cpp
# (tests/unit/tst_tuningdictionary.cpp checks that they agree).
GAINS = {
    "servo-can": [(60, "speed-kp", 30, 1, 1000), (61, "speed-ki", 30, 0, 5000), (62, "position-kp", 60, 0, 1000),
                  (63, "speed-feedforward", 100, 0, 100), (64, "acceleration", 6, 1, 32767),
                  (65, "torque-feedforward", 100, 0, 100)],
    "servo-modbus": [(5, "speed-kp", 40, 1, 1000), (6, "speed-ki", 30, 0, 5000), (7, "position-kp", 60, 0, 1000),
                     (8, "speed-feedforward", 100, 0, 100), (9, "torque-feedforward", 100, 0, 100)],
}

for family, gains in GAINS.items():
    with open(os.path.join(HERE, "..", family + ".json"), encoding="utf-8") as f:
        d = json.load(f)
    d["description"] = {
        "en": d["description"]["en"] + " As DriveDesk's simulator answers it: its own loop gains are named (not a real drive's).",
        "zh": d["description"]["zh"] + "（DriveDesk 模拟器版本：列出模拟器自己的环路增益，并非真实驱动器的参数。）",
    }
    byIndex = {p["index"]: p for p in d["parameters"]}
    tuning = []
    for index, role, default, lo, hi in gains:
        p = byIndex[index]
        name, unit, description = ROLES[role]
        p.update({"name": name, "description": description, "unit": unit, "min": lo, "max": hi, "default": default})
        tuning.append({"key": p["key"], "role": role})
    d["tuning"] = tuning
    with open(os.path.join(HERE, family + ".json"), "w", encoding="utf-8") as f:
        json.dump(d, f, ensure_ascii=False, indent=1)
        f.write("\n")
