#!/usr/bin/python3
"""Check a run's XDMF index against its snapshots: well-formed XML, one temporal grid per
snapshot, and every DataItem naming an existing file and dataset of the declared dimensions
(what ParaView will read).   usage: check_xdmf.py RUN_DIR EXPECTED_SNAPSHOTS"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def main():
    run, expected = sys.argv[1], int(sys.argv[2])
    root = ET.parse(os.path.join(run, "run.xmf")).getroot()
    grids = root.findall("./Domain/Grid/Grid")
    if len(grids) != expected:
        print(f"FAIL: {len(grids)} grids in run.xmf, expected {expected}")
        return 1
    items = 0
    for item in root.iter("DataItem"):
        name, path = item.text.strip().split(":")
        dims = tuple(int(n) for n in item.attrib["Dimensions"].split())
        with h5py.File(os.path.join(run, name), "r") as f:
            if path not in f:
                print(f"FAIL: {name} has no {path}")
                return 1
            if f[path].shape != dims:
                print(f"FAIL: {name}:{path} has shape {f[path].shape}, run.xmf says {dims}")
                return 1
        items += 1
    print(f"run.xmf: {len(grids)} snapshot(s), {items} data items, all present with the declared shapes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
