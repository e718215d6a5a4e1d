"""Run by pvpython (paraview_client.py): opens run.xmf with the XDMF reader a user picks and
checks what ParaView sees against the h5py reads in EXPECTED, traces stream lines of both
velocity vectors with Stream Tracer, then renders a slice to PNG.

usage: pvpython check_in_paraview.py RUN_XMF EXPECTED_JSON PNG
"""
import json
import math
import os
import sys

from paraview import servermanager
from paraview.simple import (CellDatatoPointData, ColorBy, GetActiveViewOrCreate, MergeBlocks, GetAnimationScene,
                             GetColorTransferFunction, Render, ResetCamera, SaveScreenshot, Show,
                             Slice, StreamTracer, Threshold, Xdmf3ReaderS)
from vtkmodules.numpy_interface import dataset_adapter as dsa

xmf, expected_path, png = sys.argv[1:4]
with open(expected_path) as f:
    expected = json.load(f)
failures = []


def fail(text):
    failures.append(text)
    print("FAIL: " + text)


reader = Xdmf3ReaderS(FileName=xmf)
times = list(reader.TimestepValues)
if len(times) != len(expected["times"]) or any(abs(a - b) > 1e-9 for a, b in zip(times, expected["times"])):
    fail(f"time steps {times}, the snapshots say {expected['times']}")
last = times[-1]
reader.UpdatePipeline(last)
bounds = reader.GetDataInformation().GetBounds()
if any(abs(a - b) > 1e-12 for a, b in zip(bounds, expected["bounds"])):
    fail(f"bounds {bounds}, the grid's faces give {expected['bounds']}")
arrays = set(reader.CellData.keys())
for name in expected["fields"] + ["cell_flags"]:
    if name not in arrays:
        fail(f"cell array {name} missing")

# The two blocks: the cells (a rectilinear grid) and the openings (quadrilaterals).
data = servermanager.Fetch(reader)
blocks = {}
iterator = data.NewIterator()
iterator.InitTraversal()
while not iterator.IsDoneWithTraversal():
    leaf = iterator.GetCurrentDataObject()
    kind = "cells" if leaf.IsA("vtkRectilinearGrid") else "openings"
    blocks[kind] = dsa.WrapDataObject(leaf)
    iterator.GoToNextItem()
if set(blocks) != {"cells", "openings"}:
    fail(f"blocks {sorted(blocks)}, expected cells and openings")
    sys.exit(1)
cells = blocks["cells"]
if cells.GetNumberOfCells() != expected["cells"]:
    fail(f"{cells.GetNumberOfCells()} cells, expected {expected['cells']}")
for name, values in expected["vectors"].items():
    seen = cells.CellData[name]
    if seen.shape != (len(values), 3):
        fail(f"{name}: shape {seen.shape}, expected ({len(values)}, 3)")
        continue
    worst = 0.0
    for c, want in enumerate(values):
        got = [float(x) for x in seen[c]]
        if any(math.isnan(w) != math.isnan(g) for w, g in zip(want, got)):
            fail(f"{name}: cell {c} is {got}, the snapshot holds {want}")
            break
        if math.isnan(want[0]):
            continue
        worst = max(worst, max(abs(g - w) for g, w in zip(got, want)),
                    abs(math.sqrt(sum(g * g for g in got)) - math.sqrt(sum(w * w for w in want))))
    if worst > 1e-12:
        fail(f"{name}: components or magnitudes differ from the snapshot by {worst:.3g}")
    print(f"{name}: {len(values)} cells, 3 components, largest difference from h5py {worst:.3g}")
openings = blocks["openings"]
for name, values in expected["openings"].items():
    got = openings.CellData[name]
    flat_got = [float(x) for x in got.flatten()]
    flat_want = [float(x) for row in values for x in (row if isinstance(row, list) else [row])]
    if len(flat_got) != len(flat_want) or any(abs(g - w) > 1e-12 for g, w in zip(flat_got, flat_want)):
        fail(f"openings/{name} differs from the snapshot")
out = [float(v) for v in openings.CellData["solids_outflow_velocity"]]
print(f"openings: {openings.GetNumberOfCells()} faces, solids outflow velocity "
      f"{min(out):.3g} to {max(out):.3g} m/s")

# A slice of the fluid cells (Threshold on cell_flags) through y, coloured by the solids fraction.
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [400, 800]
middle = 0.4 * expected["bounds"][2] + 0.6 * expected["bounds"][3]  # inside a cell, not on a face
fluid = Threshold(Input=reader, Scalars=["CELLS", "cell_flags"], LowerThreshold=1, UpperThreshold=1)
cut = Slice(Input=fluid)
cut.SliceType = "Plane"
cut.SliceType.Origin = [0.0, middle, 0.0]
cut.SliceType.Normal = [0.0, 1.0, 0.0]
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = last
view.ViewTime = last
display = Show(cut, view)
ColorBy(display, ("CELLS", "solids_fraction"))
lut = GetColorTransferFunction("solids_fraction")
lut.RescaleTransferFunction(0.0, 0.6)
display.ColorArrayName = ["CELLS", "solids_fraction"]
display.LookupTable = lut
cut.UpdatePipeline(last)
fractions = cut.CellData["solids_fraction"].GetRange()
print(f"slice: solids_fraction {fractions[0]:.3g} to {fractions[1]:.3g}")
if not fractions[1] > 0.5:
    fail(f"the slice's solids fraction reaches only {fractions[1]:.3g}; the bin is filled at 0.58")
view.CameraPosition = [0.02, -3.0, 0.5]
view.CameraFocalPoint = [0.02, 0.02, 0.5]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
Render(view)
SaveScreenshot(png, view, ImageResolution=[400, 800])
print(f"slice rendered to {png}", flush=True)

# Stream lines: Stream Tracer takes each velocity vector as it is (cell data, no Calculator),
# seeded on a line across the packed fill; each vector must give lines with points. Then the
# smoother form docs/paraview.md describes: Threshold on cell_flags, Merge Blocks (on the
# Threshold's multiblock output ParaView 5.11's Stream Tracer returns no lines), Cell Data to
# Point Data.
b = expected["bounds"]


def trace(source, association, name):
    tracer = StreamTracer(Input=source, SeedType="Line")
    tracer.Vectors = [association, name]
    y = 0.4 * b[2] + 0.6 * b[3]
    z = b[4] + 0.3 * (b[5] - b[4])
    tracer.SeedType.Point1 = [b[0] + 0.15 * (b[1] - b[0]), y, z]
    tracer.SeedType.Point2 = [b[0] + 0.85 * (b[1] - b[0]), y, z]
    tracer.SeedType.Resolution = 10
    tracer.MaximumStreamlineLength = b[5] - b[4]
    tracer.UpdatePipeline(last)
    info = tracer.GetDataInformation()
    points, lines = info.GetNumberOfPoints(), info.GetNumberOfCells()
    print(f"stream tracer on {association.lower()} {name}: {lines} lines, {points} points")
    if points == 0 or lines == 0:
        fail(f"Stream Tracer on {association.lower()} {name} gave no lines")


for name in expected["vectors"]:
    trace(reader, "CELLS", name)
merged = MergeBlocks(Input=Threshold(Input=reader, Scalars=["CELLS", "cell_flags"],
                                     LowerThreshold=1, UpperThreshold=1))
trace(CellDatatoPointData(Input=merged), "POINTS", "solids_velocity")

# Leave without tearing down the render window: under Xvfb that teardown can fail with a GLX
# error after everything is written.
os._exit(1 if failures else 0)
