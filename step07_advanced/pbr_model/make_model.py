"""Make the technique's model: ``python -m step07_advanced.pbr_model.make_model [--out FILE] [--force]``.

A sci-fi power cell turned on a lathe (numpy geometry with UVs: u around the axis, v along the profile, top
row = top of the cell) with five procedural 256² maps in glTF's metallic-roughness workflow: base colour
(sRGB), metallic-roughness (G = roughness, B = metallic), a tangent-space normal map (panel seams, rivets),
ambient occlusion (R) and emissive (sRGB, a glowing band). trimesh writes it as one GLB (~250 KB) that
:func:`gandalf_core.resources.load_gltf` reads back. The committed ``models/power_cell.glb`` came from here.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

MODEL = Path(__file__).resolve().parent / "models" / "power_cell.glb"
TEXTURE_SIZE = 256
SEGMENTS = 48

#: The lathe profile, bottom centre to top centre: (tag, [(radius, height), ...]) per segment. Segments meet
#: at hard edges (their end points are duplicated with their own normals); arcs are smooth within.
PAINT, METAL, GLOW, RUBBER = "paint", "metal", "glow", "rubber"


def _arc(center: tuple[float, float], radii: tuple[float, float], a0: float, a1: float, n: int) -> list:
    t = np.radians(np.linspace(a0, a1, n))
    return list(zip(center[0] + radii[0] * np.cos(t), center[1] + radii[1] * np.sin(t)))


def profile() -> list[tuple[str, list[tuple[float, float]]]]:
    return [
        (RUBBER, [(0.0, 0.0), (0.56, 0.0)]),
        (RUBBER, [(0.56, 0.0), (0.56, 0.14)]),
        (METAL, [(0.56, 0.14), (0.49, 0.21)]),
        (PAINT, [(0.49, 0.21), (0.49, 0.78)]),
        (METAL, [(0.49, 0.78), (0.43, 0.83)]),
        (GLOW, [(0.43, 0.83), (0.43, 1.01)]),
        (METAL, [(0.43, 1.01), (0.49, 1.06)]),
        (PAINT, [(0.49, 1.06), (0.49, 1.48)]),
        (METAL, _arc((0.24, 1.48), (0.25, 0.3), 0.0, 90.0, 10)),
        (METAL, [(0.24, 1.78), (0.2, 1.78)]),
        (METAL, [(0.2, 1.78), (0.2, 1.9)]),
        (METAL, _arc((0.0, 1.9), (0.2, 0.12), 0.0, 90.0, 8)),
    ]


def lathe(segments: int = SEGMENTS) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list]:
    """(positions, normals, uvs (engine convention: v = 0 at the top), triangle indices, [(tag, v0, v1)])."""
    parts = profile()
    lengths = [np.sum(np.linalg.norm(np.diff(np.asarray(pts), axis=0), axis=1)) for _, pts in parts]
    total = float(np.sum(lengths))
    theta = np.linspace(0.0, 2.0 * np.pi, segments + 1)
    positions, normals, uvs, indices, bands = [], [], [], [], []
    base, walked = 0, 0.0
    for (tag, pts), length in zip(parts, lengths):
        p = np.asarray(pts, dtype=np.float64)
        tangent = np.gradient(p, axis=0)
        tangent /= np.linalg.norm(tangent, axis=1, keepdims=True)
        normal2 = np.stack([tangent[:, 1], -tangent[:, 0]], axis=1)  # outward in the (r, y) plane
        s = walked + np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
        v = 1.0 - s / total
        bands.append((tag, float(v[-1]), float(v[0])))
        walked += length
        cos, sin = np.cos(theta)[None, :], np.sin(theta)[None, :]
        ring = np.stack([p[:, :1] * cos, np.broadcast_to(p[:, 1:], (len(p), segments + 1)), -p[:, :1] * sin], -1)
        nrm = np.stack([normal2[:, :1] * cos, np.broadcast_to(normal2[:, 1:], (len(p), segments + 1)),
                        -normal2[:, :1] * sin], -1)
        uv = np.stack([np.broadcast_to(theta[None, :] / (2 * np.pi), ring.shape[:2]),
                       np.broadcast_to(v[:, None], ring.shape[:2])], -1)
        positions.append(ring.reshape(-1, 3))
        normals.append(nrm.reshape(-1, 3))
        uvs.append(uv.reshape(-1, 2))
        cols = segments + 1
        for i in range(len(p) - 1):
            for j in range(segments):
                a, b = base + i * cols + j, base + i * cols + j + 1
                c, d = a + cols, b + cols
                indices += [(a, b, c), (b, d, c)]
        base += len(p) * cols
    pos, nrm, uv = np.concatenate(positions), np.concatenate(normals), np.concatenate(uvs)
    tri = np.asarray(indices, dtype=np.int64)
    # Wind every triangle counter-clockwise seen from outside (its face normal along the vertex normals).
    face = np.cross(pos[tri[:, 1]] - pos[tri[:, 0]], pos[tri[:, 2]] - pos[tri[:, 0]])
    flip = np.sum(face * nrm[tri].sum(axis=1), axis=1) < 0.0
    tri[flip] = tri[flip][:, ::-1]
    area = np.linalg.norm(face, axis=1)
    return pos, nrm, uv, tri[area > 1e-12], bands


def _rows_by_band(bands: list, size: int) -> np.ndarray:
    v = (np.arange(size) + 0.5) / size
    tags = np.full(size, RUBBER, dtype=object)
    for tag, v0, v1 in bands:
        tags[(v >= v0) & (v <= v1)] = tag
    return tags


def textures(bands: list, size: int = TEXTURE_SIZE) -> dict[str, np.ndarray]:
    """The five maps as float arrays in [0, 1] (H, W, 3), top row first; colours sRGB-encoded."""
    from gandalf_core.resources import value_noise
    from step07_advanced.showcase.textures import normal_map_from_height

    tags = _rows_by_band(bands, size)
    row_is = {t: (tags == t)[:, None] for t in (PAINT, METAL, GLOW, RUBBER)}
    y, x = np.mgrid[0:size, 0:size].astype(np.float64) + 0.5
    u, v = x / size, y / size
    grain = value_noise(size, seed=5, cells=32, octaves=4).pixels[..., 0] / 255.0
    scratches = value_noise(size, seed=9, cells=64, octaves=2).pixels[..., 0] / 255.0
    # Panel seams on the paint: 8 vertical seams around, and a seam line at every band boundary.
    seam_u = np.abs(((u * 8.0) % 1.0) - 0.5) * 2.0  # 1 at a seam, 0 between
    seams = np.clip((seam_u - 0.94) / 0.06, 0.0, 1.0) * row_is[PAINT]
    boundaries = np.zeros(size)
    for _, v0, _v1 in bands:
        boundaries = np.maximum(boundaries, np.exp(-((v[:, 0] - v0) * size / 1.2) ** 2))
    seams = np.maximum(seams, boundaries[:, None] * 0.8)
    # Rivets: small domes on the metal bands, 24 around.
    ru = ((u * 24.0) % 1.0 - 0.5) / 24.0 * size
    rivet_rows = np.zeros(size, dtype=bool)
    for tag, v0, v1 in bands:
        if tag == METAL and (v1 - v0) * size > 8:
            rivet_rows |= np.abs(v[:, 0] - (v0 + v1) / 2) * size < 3.0
    rivets = np.clip(1.0 - (ru**2) / 6.0, 0.0, 1.0) * rivet_rows[:, None]
    # Glow stripes: the band's emissive pattern.
    stripes = 0.55 + 0.45 * np.cos(u * 2 * np.pi * 16.0) ** 2
    height = 0.5 - 0.5 * seams + 0.35 * rivets + 0.04 * grain
    paint = np.array([0.85, 0.42, 0.12]) * (0.9 + 0.2 * grain[..., None])
    paint = np.where((v < 0.5)[..., None], paint, np.array([0.16, 0.45, 0.55]) * (0.9 + 0.2 * grain[..., None]))
    metal = np.array([0.80, 0.79, 0.76]) * (0.92 + 0.1 * scratches[..., None])
    glow = np.array([0.12, 0.14, 0.15])
    rubber = np.array([0.05, 0.05, 0.055]) * (0.8 + 0.4 * grain[..., None])
    base = (row_is[PAINT][..., None] * paint + row_is[METAL][..., None] * metal + row_is[GLOW][..., None] * glow
            + row_is[RUBBER][..., None] * rubber)
    base = base * (1.0 - 0.6 * seams[..., None])
    metallic = 1.0 * row_is[METAL] + 0.0 * row_is[PAINT] + 0.2 * row_is[GLOW] + 0.0 * row_is[RUBBER]
    metallic = np.broadcast_to(metallic, (size, size)) * (1.0 - seams)
    roughness = (0.28 + 0.3 * scratches) * row_is[METAL] + (0.5 + 0.15 * grain) * row_is[PAINT] \
        + 0.35 * row_is[GLOW] + 0.9 * row_is[RUBBER]
    roughness = np.clip(roughness + 0.3 * seams, 0.0, 1.0)
    occlusion = np.clip(1.0 - 0.7 * seams, 0.0, 1.0)
    occlusion = occlusion * (1.0 - 0.35 * np.exp(-((v - bands[0][1]) * size / 12.0) ** 2))  # under the base
    emissive = row_is[GLOW][..., None] * np.array([0.25, 0.85, 1.0]) * stripes[..., None]
    from gandalf_core.resources import linear_to_srgb

    normal = normal_map_from_height(height, strength=3.0) * 0.5 + 0.5
    zeros = np.zeros((size, size))
    return {
        "base_color": linear_to_srgb(np.clip(base, 0.0, 1.0)),
        "metallic_roughness": np.stack([zeros, roughness, metallic], axis=-1),
        "normal": np.clip(normal, 0.0, 1.0),
        "occlusion": np.stack([occlusion] * 3, axis=-1),
        "emissive": linear_to_srgb(np.clip(emissive, 0.0, 1.0)),
    }


def build_glb() -> bytes:
    """The GLB bytes of the power cell (deterministic)."""
    import trimesh
    from PIL import Image

    pos, nrm, uv, tri, bands = lathe()
    maps = textures(bands)

    def image(a: np.ndarray) -> Image.Image:
        return Image.fromarray(np.rint(np.clip(a, 0.0, 1.0) * 255.0).astype(np.uint8), mode="RGB")

    material = trimesh.visual.material.PBRMaterial(
        name="power_cell", baseColorTexture=image(maps["base_color"]),
        metallicRoughnessTexture=image(maps["metallic_roughness"]), normalTexture=image(maps["normal"]),
        occlusionTexture=image(maps["occlusion"]), emissiveTexture=image(maps["emissive"]),
        emissiveFactor=[1.0, 1.0, 1.0], metallicFactor=1.0, roughnessFactor=1.0, baseColorFactor=[255] * 4)
    # trimesh's UVs have v = 0 at the bottom of the image (OpenGL); glTF's and the engine's at the top.
    mesh = trimesh.Trimesh(pos, tri, vertex_normals=nrm, process=False,
                           visual=trimesh.visual.TextureVisuals(uv=np.stack([uv[:, 0], 1.0 - uv[:, 1]], -1),
                                                                material=material))
    scene = trimesh.Scene()
    scene.add_geometry(mesh, geom_name="power_cell", node_name="power_cell")
    return trimesh.exchange.gltf.export_glb(scene, include_normals=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=MODEL, help=f"where to write the GLB (default: {MODEL})")
    parser.add_argument("--force", action="store_true", help="overwrite an existing file")
    args = parser.parse_args(argv)
    if args.out.exists() and not args.force:
        print(f"{args.out} exists; pass --force to overwrite it", file=sys.stderr)
        return 1
    data = build_glb()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_bytes(data)
    print(f"wrote {args.out} ({len(data) / 1024:.0f} KB)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
