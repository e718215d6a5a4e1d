"""Small helpers the two-fluid check scripts share: the snapshots of a run, in time order, and
the cell volumes of their grid."""
import glob
import os

import h5py
import numpy as np

G = 9.81  # |g| of every deck in this folder [m/s²]


def snapshot_paths(run_dir):
    paths = sorted(glob.glob(os.path.join(run_dir, "snapshot_*.h5")))
    if not paths:
        raise SystemExit(f"FAIL: no snapshot in {run_dir}")
    return paths


class Snapshot:
    """The fields of one snapshot as numpy arrays indexed [k, j, i] (z, y, x)."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            self.time = float(f.attrs["time"])
            self.fields = {name: f["fields/" + name][:] for name in f["fields"]}
            self.x_faces = f["grid/x_faces"][:]
            self.y_faces = f["grid/y_faces"][:]
            self.z_faces = f["grid/z_faces"][:]
        self.dz = np.diff(self.z_faces)
        self.z_centres = 0.5 * (self.z_faces[1:] + self.z_faces[:-1])
        self.volumes = (self.dz[:, None, None] * np.diff(self.y_faces)[None, :, None]
                        * np.diff(self.x_faces)[None, None, :])
        self.area = (self.x_faces[-1] - self.x_faces[0]) * (self.y_faces[-1] - self.y_faces[0])

    def __getitem__(self, name):
        return self.fields[name]

    def solids_volume(self):
        """Σ ε_s V over the fluid cells [m³]."""
        return float(np.nansum(self["solids_fraction"] * self.volumes))

    def column(self, name):
        """A field averaged over x and y: a profile along z."""
        return np.nanmean(self[name], axis=(1, 2))
