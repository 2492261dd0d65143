"""airis.Dataset: reads a dataset written by `airis dataset` (docs/dataset-format.md).

    ds = airis.Dataset("out/demo_dataset")
    cam = ds.cameras["front"]
    frame = cam[0]            # dict: rgb (H, W, 3) uint8, depth_m (H, W) float32, class_id, ...
    imu = ds.stream("drone1.imu")   # structured array, columns as in the file
    torch_ds = cam.torch()    # a torch.utils.data.Dataset (needs PyTorch)
    scan = ds.lidars["drone1.lidar"][0]   # dict: points (structured array), T_WS, time_ns, ...
    xyz_W = ds.lidars["drone1.lidar"].world_points(0)   # (N, 3) world NED, motion distortion undone
"""

import csv
import json
import os

import numpy as np

__all__ = ["Dataset", "CameraFrames", "LidarScans", "read_pcd"]


def _read_png(path):
    from PIL import Image  # Debian python3-pil
    with Image.open(path) as im:
        if im.mode in ("I;16", "I;16B", "I"):
            return np.array(im, dtype=np.uint16) if im.mode != "I" else \
                np.array(im).astype(np.uint16)
        return np.array(im)


def _read_instance_png(path, fmt):
    """Instance ids (H, W) uint32 of a seg_instance PNG in the manifest's format: rgb24 (8-bit
    RGB, id = R + 256 G + 65536 B, COCO panoptic's encoding) or gray16 (16-bit grey)."""
    image = _read_png(path)
    if fmt == "rgb24":
        if image.ndim != 3 or image.dtype != np.uint8:
            raise ValueError(f"{path}: expected an 8-bit RGB PNG (instance_format rgb24)")
        rgb = image[:, :, :3].astype(np.uint32)
        return rgb[:, :, 0] | (rgb[:, :, 1] << 8) | (rgb[:, :, 2] << 16)
    if image.ndim != 2:
        raise ValueError(f"{path}: expected a 16-bit grey PNG (instance_format {fmt})")
    return image.astype(np.uint32)


def _read_csv(path):
    """A CSV with a header as a structured array (ints, floats, else text)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return np.zeros(0)
    header, body = rows[0], rows[1:]
    columns = list(zip(*body)) if body else [[] for _ in header]
    arrays = []
    for name, values in zip(header, columns):
        for kind in (np.int64, np.float64):
            try:
                arrays.append(np.array(values, dtype=kind))
                break
            except ValueError:
                continue
        else:
            arrays.append(np.array(values, dtype=object))
    out = np.empty(len(body), dtype=[(h, a.dtype) for h, a in zip(header, arrays)])
    for h, a in zip(header, arrays):
        out[h] = a
    return out


_PCD_TYPES = {"F": "<f", "U": "<u", "I": "<i"}


def read_pcd(path):
    """A binary PCD file (airis's lidar scans) as a NumPy structured array, one field per PCD field."""
    with open(path, "rb") as f:
        data = f.read()
    marker = b"DATA binary\n"
    start = data.find(marker)
    if start < 0:
        raise ValueError(f"{path}: not a binary PCD file")
    header = {}
    for line in data[:start].decode("ascii").splitlines():
        if line and not line.startswith("#"):
            key, *values = line.split()
            header[key] = values
    dtype = np.dtype([(name, _PCD_TYPES[t] + size) for name, t, size in
                      zip(header["FIELDS"], header["TYPE"], header["SIZE"])])
    return np.frombuffer(data, dtype=dtype, count=int(header["POINTS"][0]),
                         offset=start + len(marker))


def _rotation(w, x, y, z):
    """The rotation matrix of a unit quaternion."""
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _exp_so3(r):
    """Rotation matrices exp([r]x) of rotation vectors r (N, 3) (Rodrigues)."""
    angle = np.linalg.norm(r, axis=1)
    safe = np.where(angle > 1e-12, angle, 1.0)
    k = r / safe[:, None]
    K = np.zeros((len(r), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -k[:, 2], k[:, 1], -k[:, 0]
    K[:, 1, 0], K[:, 2, 0], K[:, 2, 1] = k[:, 2], -k[:, 1], k[:, 0]
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return np.eye(3)[None] + s * K + (1 - c) * (K @ K)


class LidarScans:
    """The written scans of one lidar: len(), [i] -> dict, world_points(i), poses, pattern.

    Scan dict keys: index, time_ns, points (structured array of the PCD fields: x, y, z in the
    sensor frame at each point's firing time, range_m, intensity, time_offset_s, ring, column,
    instance_id, class_id), T_WS (4, 4) float64 sensor -> world NED at the scan time.
    """

    def __init__(self, root, manifest_entry):
        self.name = manifest_entry["name"]
        self.info = manifest_entry
        self.dir = os.path.join(root, self.name)
        self.poses = _read_csv(os.path.join(self.dir, "poses.csv"))

    def __len__(self):
        return len(self.poses)

    def pose(self, i):
        p = self.poses[i]
        T = np.eye(4)
        T[:3, :3] = _rotation(*(float(p[f"attitude_sensor_to_ned_{c}"]) for c in "wxyz"))
        T[:3, 3] = [p["position_ned_x_m"], p["position_ned_y_m"], p["position_ned_z_m"]]
        return T

    def __getitem__(self, i):
        if not -len(self) <= i < len(self):
            raise IndexError(f"lidar '{self.name}' has {len(self)} scans (asked for {i})")
        i = i % len(self)
        index = int(self.poses[i]["scan"])
        return {"index": index, "time_ns": int(self.poses[i]["time_ns"]), "T_WS": self.pose(i),
                "points": read_pcd(os.path.join(self.dir, f"{index:06d}.pcd"))}

    def world_points(self, i):
        """Scan i's points in world NED (N, 3), each from the sensor pose at its firing time
        (docs/dataset-format.md, "Lidar scans": constant velocity and angular velocity over the
        sweep)."""
        scan = self[i]
        p = self.poses[i % len(self)]
        pts = scan["points"]
        xyz = np.stack([pts["x"], pts["y"], pts["z"]], axis=1).astype(np.float64)
        dt = -pts["time_offset_s"].astype(np.float64)
        v = np.array([p[f"velocity_ned_{a}_m_s"] for a in "xyz"], dtype=np.float64)
        w = np.array([p[f"angular_velocity_sensor_{a}_rad_s"] for a in "xyz"], dtype=np.float64)
        R_WS = scan["T_WS"][:3, :3]
        R = R_WS[None] @ _exp_so3(-dt[:, None] * w[None])
        origin = scan["T_WS"][:3, 3][None] - dt[:, None] * v[None]
        return origin + np.einsum("nij,nj->ni", R, xyz)


class CameraFrames:
    """The written frames of one camera: len(), [i] -> dict of arrays, poses, intrinsics.

    Frame dict keys (when written): rgb (H, W, 3) uint8; depth_m (H, W) float32 metres (the
    16-bit PNG times its unit, or the .npy floats with --formats npy; 0 PNG values -> inf, no
    return); depth_raw (H, W) uint16; class_id (H, W) uint8; instance_id (H, W) uint32 (decoded
    from the format the manifest records: rgb24 or gray16); normals (H, W, 3) float32; time_ns;
    T_WC (4, 4) float64 camera optical frame -> world NED.
    """

    def __init__(self, root, manifest_entry):
        self.root = root
        self.name = manifest_entry["name"]
        self.info = manifest_entry
        self.dir = os.path.join(root, self.name)
        self.poses = _read_csv(os.path.join(self.dir, "poses.csv"))
        self.width = manifest_entry["width"]
        self.height = manifest_entry["height"]
        self.K = np.array([[manifest_entry["fx"], 0.0, manifest_entry["cx"]],
                           [0.0, manifest_entry["fy"], manifest_entry["cy"]],
                           [0.0, 0.0, 1.0]])
        depth = manifest_entry.get("depth_png") or {}
        self.depth_unit_m = depth.get("unit_m")
        # Datasets of format_version 2 and earlier record no format: 16-bit grey.
        self.instance_format = (manifest_entry.get("seg_instance") or {}).get("format", "gray16")

    def __len__(self):
        return len(self.poses)

    def _file(self, kind, index, ext):
        return os.path.join(self.dir, kind, f"{index:06d}.{ext}")

    def pose(self, i):
        p = self.poses[i]
        w, x, y, z = (float(p[f"attitude_cam_to_ned_{c}"]) for c in "wxyz")
        R = np.array([
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
        T = np.eye(4)
        T[:3, :3] = R
        T[:3, 3] = [p["position_ned_x_m"], p["position_ned_y_m"], p["position_ned_z_m"]]
        return T

    def __getitem__(self, i):
        if not -len(self) <= i < len(self):
            raise IndexError(f"camera '{self.name}' has {len(self)} frames (asked for {i})")
        i = i % len(self)
        index = int(self.poses[i]["frame"])
        out = {"index": index, "time_ns": int(self.poses[i]["time_ns"]), "T_WC": self.pose(i)}
        rgb = self._file("rgb", index, "png")
        if os.path.exists(rgb):
            out["rgb"] = _read_png(rgb)[:, :, :3]
        depth_npy = self._file("depth", index, "npy")
        depth_png = self._file("depth", index, "png")
        if os.path.exists(depth_png):
            raw = _read_png(depth_png)
            out["depth_raw"] = raw
            metres = raw.astype(np.float32) * np.float32(self.depth_unit_m)
            metres[raw == 0] = np.inf
            out["depth_m"] = metres
        if os.path.exists(depth_npy):
            out["depth_m"] = np.load(depth_npy)
        seg_class = self._file("seg_class", index, "png")
        if os.path.exists(seg_class):
            out["class_id"] = _read_png(seg_class)
        seg_instance = self._file("seg_instance", index, "png")
        if os.path.exists(seg_instance):
            out["instance_id"] = _read_instance_png(seg_instance, self.instance_format)
        normals = self._file("normals", index, "npy")
        if os.path.exists(normals):
            out["normals"] = np.load(normals)
        return out

    def torch(self, keys=("rgb", "depth_m", "class_id", "instance_id")):
        """A torch.utils.data.Dataset of this camera (requires PyTorch, Debian python3-torch).

        Items are dicts of tensors: rgb float32 (3, H, W) in [0, 1]; depth_m float32 (1, H, W)
        metres (inf: no return); class_id int64 (H, W); instance_id int64 (H, W) (torch has no
        uint32: the ids are widened); T_WC float64 (4, 4); K float64 (3, 3); time_ns int64.
        """
        return _torch_dataset(self, keys)


def _torch_dataset(frames, keys):
    import torch
    from torch.utils.data import Dataset as TorchDataset

    class _FramesDataset(TorchDataset):
        def __len__(self):
            return len(frames)

        def __getitem__(self, i):
            f = frames[i]
            out = {"T_WC": torch.from_numpy(f["T_WC"]), "K": torch.from_numpy(frames.K),
                   "time_ns": torch.tensor(f["time_ns"], dtype=torch.int64)}
            if "rgb" in keys and "rgb" in f:
                out["rgb"] = torch.from_numpy(np.ascontiguousarray(
                    f["rgb"].transpose(2, 0, 1))).float() / 255.0
            if "depth_m" in keys and "depth_m" in f:
                out["depth_m"] = torch.from_numpy(f["depth_m"])[None]
            for k in ("class_id", "instance_id"):
                if k in keys and k in f:
                    out[k] = torch.from_numpy(f[k].astype(np.int64))
            return out

    return _FramesDataset()


class Dataset:
    """A dataset folder: manifest, labels, cameras (CameraFrames by name), lidars (LidarScans by
    folder name, e.g. 'drone1.lidar') and streams."""

    def __init__(self, root):
        manifest = os.path.join(root, "manifest.json")
        if not os.path.exists(manifest):
            raise FileNotFoundError(f"{root}: no manifest.json (not a dataset written by airis)")
        with open(manifest) as f:
            self.manifest = json.load(f)
        if self.manifest.get("format") != "airis-dataset":
            raise ValueError(f"{manifest}: format is {self.manifest.get('format')!r}, "
                             "expected 'airis-dataset'")
        self.root = root
        self.complete = bool(self.manifest.get("complete"))
        labels = os.path.join(root, "labels.json")
        self.labels = json.load(open(labels)) if os.path.exists(labels) else {}
        self.classes = {c["id"]: c["name"] for c in self.labels.get("classes", [])}
        self.cameras = {c["name"]: CameraFrames(root, c) for c in self.manifest.get("cameras", [])}
        self.lidars = {l["name"]: LidarScans(root, l) for l in self.manifest.get("lidars", [])}

    @property
    def streams(self):
        """Names of the stream files ('drone1.truth', 'drone1.imu', 'collisions', ...)."""
        names = []
        for f in sorted(os.listdir(self.root)):
            base, ext = os.path.splitext(f)
            if ext in (".npy", ".csv") and base not in ("checksums",):
                names.append(base)
        return names

    def stream(self, name):
        """A stream as a structured array (.npy as written; .csv parsed, ints and floats typed)."""
        npy = os.path.join(self.root, name + ".npy")
        if os.path.exists(npy):
            return np.load(npy)
        path = os.path.join(self.root, name + ".csv")
        if not os.path.exists(path):
            raise KeyError(f"{self.root}: no stream {name!r} (there are: {', '.join(self.streams)})")
        return _read_csv(path)

    def __repr__(self):
        parts = [f"{k} {len(v)} frames" for k, v in self.cameras.items()]
        parts += [f"{k} {len(v)} scans" for k, v in self.lidars.items()]
        return f"<airis.Dataset {self.root!r}: {', '.join(parts)}>"
