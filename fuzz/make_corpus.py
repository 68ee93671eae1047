#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora, one folder per target, from the project's scenes and the shared assets.

Seeds are generated rather than committed: the assets are not ours to copy, and most are too large to mutate
quickly. Each target's input is a single file, so what a seed refers to is made self-contained or absolute:
scene files name textures and models by absolute path, glTF buffers and images become data URIs (with GLB
versions), small .glb exports (Draco- and meshopt-compressed meshes) are taken as they are, Radiance pictures are cut to a few scanlines, and PNG seeds are small images in each PNG colour type.
Usage: make_corpus.py PROJECT_DIR ASSETS_DIR OUT_DIR
"""
import base64
import json
import pathlib
import struct
import sys
import zlib

MAX_SEED_BYTES = 1 << 20  # larger inputs slow every execution that mutates them
BOX = "BoxTextured/glTF-Embedded/BoxTextured.gltf"


def write(folder, name, data):
    if len(data) > MAX_SEED_BYTES:
        return
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def small_file(path):
    return path.is_file() and path.stat().st_size <= MAX_SEED_BYTES


def absolute_paths(value, folder, assets):
    """Replaces strings naming a small file relative to `folder` with its absolute path. A shared asset
    ("asset:P") too large to load at fuzzing speed is replaced by the small embedded box model."""
    if isinstance(value, dict):
        return {k: absolute_paths(v, folder, assets) for k, v in value.items()}
    if isinstance(value, list):
        return [absolute_paths(v, folder, assets) for v in value]
    if isinstance(value, str) and value.startswith("asset:"):
        asset = assets / value[len("asset:"):]
        return str((asset if small_file(asset) else assets / BOX).resolve())
    if isinstance(value, str) and small_file(folder / value):
        return str((folder / value).resolve())
    return value


def scene_seeds(project, assets, out):
    for scene in sorted((project / "scenes").glob("*.json")):
        doc = absolute_paths(json.loads(scene.read_text()), scene.parent, assets)
        write(out, scene.name, json.dumps(doc, indent=1))
    box = assets / BOX
    if box.is_file():
        doc = {"camera": {"position": [0, 1, 4], "target": [0, 0, 0]}, "ambient": 0.1,
               "objects": [{"gltf": str(box.resolve()), "transform": {"scale": 2}}],
               "lights": [{"position": [1, 2, 3], "radius": 10, "luminous_power": 200}]}
        write(out, "gltf-object.json", json.dumps(doc, indent=1))


def data_uri(mime, data):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())


def glb(doc, binary):
    """A GLB container: the JSON chunk, then the BIN chunk holding buffer 0."""
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


COMPONENT_BYTES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
INDEX_FORMAT = {5121: "B", 5123: "H", 5125: "I"}
KEPT_TRIANGLES = 64


def reduce_geometry(doc, buffers):
    """Keeps the first KEPT_TRIANGLES triangles of each indexed primitive and the vertices they use, repacking the
    bytes still referenced into one buffer: a model's structure at a few kilobytes, which mutates quickly."""
    accessors, views = doc.get("accessors", []), doc.get("bufferViews", [])

    def element(a):
        return COMPONENT_BYTES[a["componentType"]] * COMPONENTS[a["type"]]

    def view_bytes(view):
        data = buffers[view["buffer"]]
        return data[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]

    for mesh in doc.get("meshes", []):
        for primitive in mesh.get("primitives", []):
            if "indices" not in primitive:
                continue
            indices = accessors[primitive["indices"]]
            indices["count"] = min(indices["count"], 3 * KEPT_TRIANGLES)
            fmt = INDEX_FORMAT[indices["componentType"]]
            raw = view_bytes(views[indices["bufferView"]])[indices.get("byteOffset", 0):]
            used = max(struct.unpack_from("<%d%s" % (indices["count"], fmt), raw)) + 1
            for attribute in primitive["attributes"].values():
                accessors[attribute]["count"] = min(accessors[attribute]["count"], used)
    needed = {}
    for a in accessors:
        if "bufferView" in a:
            view = views[a["bufferView"]]
            size = a.get("byteOffset", 0) + (a["count"] - 1) * view.get("byteStride", element(a)) + element(a)
            needed[a["bufferView"]] = max(needed.get(a["bufferView"], 0), size)
    packed = b""
    for index, view in enumerate(views):
        data = view_bytes(view)[:needed.get(index, view["byteLength"])]
        view.update(buffer=0, byteOffset=len(packed), byteLength=len(data))
        packed += data + b"\0" * (-len(data) % 4)
    doc["buffers"] = [{"byteLength": len(packed)}]
    return [packed]


def gltf_seeds(project, assets, out):
    checker = (project / "scenes/textures/checker.png").read_bytes()
    for model in sorted(assets.rglob("*.gltf")):
        doc = json.loads(model.read_text())
        buffers = []
        for buffer in doc.get("buffers", []):
            uri = buffer.get("uri", "")
            buffers.append(base64.b64decode(uri.split(",", 1)[1]) if uri.startswith("data:")
                           else (model.parent / uri).read_bytes())
        # Large textures are replaced by a small PNG: the decoder has its own target.
        for image in doc.get("images", []):
            if "uri" in image and not image["uri"].startswith("data:"):
                path = model.parent / image["uri"]
                image["uri"] = data_uri("image/png", checker) if not small_file(path) or path.stat().st_size > 65536 \
                    else data_uri("image/jpeg" if path.suffix == ".jpg" else "image/png", path.read_bytes())
        sparse = any("sparse" in a for a in doc.get("accessors", []))  # reduce_geometry does not rewrite those
        if any(len(b) > 65536 for b in buffers) and not sparse:
            buffers = reduce_geometry(doc, buffers)
        embedded = json.loads(json.dumps(doc))
        for buffer, data in zip(embedded.get("buffers", []), buffers):
            buffer["uri"] = data_uri("application/octet-stream", data)
        write(out, model.stem + ".gltf", json.dumps(embedded))
        if len(buffers) == 1:
            doc["buffers"][0].pop("uri", None)
            doc["buffers"][0]["byteLength"] = len(buffers[0])
            write(out, model.stem + ".glb", glb(doc, buffers[0]))
    # Small binary exports as they are: Draco- and meshopt-compressed meshes, whose decoders the loader feeds.
    for model in sorted(assets.rglob("*.glb")):
        if model.stat().st_size <= 65536:
            write(out, model.stem + "-as-exported.glb", model.read_bytes())


def rle_scanline_end(data, start, width):
    """End offset of one new-style run-length scanline starting at `start`: 4 header bytes, then 4 channels."""
    pos = start + 4
    for _ in range(4):
        done = 0
        while done < width:
            count = data[pos]
            run = count > 128
            n = count - 128 if run else count
            pos += 2 if run else 1 + n
            done += n
    return pos


def hdr_seeds(assets, out):
    for picture in sorted(assets.rglob("*.hdr")):
        data = picture.read_bytes()
        header_end = data.index(b"\n\n") + 2
        line_end = data.index(b"\n", header_end) + 1
        width = int(data[header_end:line_end].split()[3])
        rows = 4
        pos = line_end
        for _ in range(rows):
            pos = rle_scanline_end(data, pos, width)
        resolution = b"-Y %d +X %d\n" % (rows, width)
        write(out, picture.stem + "-rows.hdr", data[:header_end] + resolution + data[line_end:pos])
    header = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n"
    write(out, "flat.hdr", header + bytes(range(64)))
    write(out, "half.exr", openexr(4, 4, 1))
    write(out, "float.exr", openexr(4, 4, 2))
    write(out, "tiled.exr", openexr_tiled(4, 4, 2, 0))
    write(out, "tiled-mipmap.exr", openexr_tiled(4, 4, 2, 1))


def openexr(width, height, pixel_type):
    """An uncompressed single-part scanline OpenEXR picture of B, G and R channels (1 half, 2 float), written by
    hand: the magic number, version 2, the required attributes, the offset table and one block a scanline."""
    def attribute(name, kind, value):
        return name + b"\0" + kind + b"\0" + struct.pack("<i", len(value)) + value
    channels = b"".join(c + b"\0" + struct.pack("<iBxxxii", pixel_type, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2) + attribute(b"channels", b"chlist", channels) +
              attribute(b"compression", b"compression", b"\0") + attribute(b"dataWindow", b"box2i", box) +
              attribute(b"displayWindow", b"box2i", box) + attribute(b"lineOrder", b"lineOrder", b"\0") +
              attribute(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0)) +
              attribute(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0.0, 0.0)) +
              attribute(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)) + b"\0")
    size = 2 if pixel_type == 1 else 4
    row_bytes = 3 * width * size
    first = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", first + y * (8 + row_bytes)) for y in range(height))
    value = struct.pack("<e", 0.5) if pixel_type == 1 else struct.pack("<f", 0.5)
    blocks = b"".join(struct.pack("<ii", y, row_bytes) + value * (3 * width) for y in range(height))
    return header + offsets + blocks


def openexr_tiled(width, height, tile, mode):
    """An uncompressed single-part tiled OpenEXR picture of float B, G and R channels in square tiles, one level
    (mode 0) or mipmapped rounding down (mode 1): the version's tiled bit, a tile description, the type field, one
    offset a tile of every level and each tile's block."""
    def attribute(name, kind, value):
        return name + b"\0" + kind + b"\0" + struct.pack("<i", len(value)) + value
    channels = b"".join(c + b"\0" + struct.pack("<iBxxxii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2 | 0x200) + attribute(b"channels", b"chlist", channels) +
              attribute(b"compression", b"compression", b"\0") + attribute(b"dataWindow", b"box2i", box) +
              attribute(b"displayWindow", b"box2i", box) + attribute(b"lineOrder", b"lineOrder", b"\0") +
              attribute(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0)) +
              attribute(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0.0, 0.0)) +
              attribute(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)) +
              attribute(b"tiles", b"tiledesc", struct.pack("<IIB", tile, tile, mode)) +
              attribute(b"type", b"string", b"tiledimage") + b"\0")
    levels = [(width, height)]
    while mode == 1 and max(levels[-1]) > 1:
        levels.append((max(levels[-1][0] // 2, 1), max(levels[-1][1] // 2, 1)))
    blocks = []
    for level, (w, h) in enumerate(levels):
        for ty in range(-(-h // tile)):
            for tx in range(-(-w // tile)):
                tw, th = min(tile, w - tx * tile), min(tile, h - ty * tile)
                data = struct.pack("<f", 0.5) * (3 * tw * th)
                blocks.append(struct.pack("<iiiii", tx, ty, level, level, len(data)) + data)
    first = len(header) + 8 * len(blocks)
    offsets, at = b"", first
    for block in blocks:
        offsets += struct.pack("<Q", at)
        at += len(block)
    return header + offsets + b"".join(blocks)


def png(width, height, colour_type, depth, rows, palette=None):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + row for row in rows)
    body = chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0))
    if palette:
        body += chunk(b"PLTE", palette)
    return b"\x89PNG\r\n\x1a\n" + body + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def texture_seeds(project, assets, out):
    write(out, "checker.png", (project / "scenes/textures/checker.png").read_bytes())
    n = 8
    grey = [bytes((x * 32 + y) % 256 for x in range(n)) for y in range(n)]
    write(out, "grey8.png", png(n, n, 0, 8, grey))
    write(out, "grey16.png", png(n, n, 0, 16, [bytes(b for v in r for b in (v, v)) for r in grey]))
    write(out, "rgb8.png", png(n, n, 2, 8, [bytes(b for v in r for b in (v, 255 - v, v // 2)) for r in grey]))
    write(out, "rgba8.png", png(n, n, 6, 8, [bytes(b for v in r for b in (v, v, 255 - v, v)) for r in grey]))
    write(out, "grey-alpha8.png", png(n, n, 4, 8, [bytes(b for v in r for b in (v, 255 - v)) for r in grey]))
    write(out, "palette4.png", png(n, n, 3, 4, [bytes(((v % 16) << 4 | (v % 16)) for v in r[: n // 2]) for r in grey],
                                   palette=bytes(range(48))))
    for webp in sorted(assets.rglob("*.webp")):
        write(out, webp.name, webp.read_bytes())
    # Formats stb_image reads but textures may not be (decodeImage refuses them by their signature): the fuzzer
    # mutates from each, so that a mutant still starting like one keeps testing the refusal.
    for name, data in other_image_formats():
        write(out, name, data)
    for jpeg in sorted(assets.rglob("*.jpg")):
        write(out, jpeg.stem + "-corner.jpg", jpeg_corner(jpeg.read_bytes()))


def other_image_formats():
    """Small images (2x2, the GIF 1x1) in Radiance RGBE, BMP, GIF, TGA, binary PPM and PSD, written by hand."""
    rgb = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255])
    rows = [rgb[0:6], rgb[6:12]]
    bmp_rows = b"".join(bytes(b for i in range(0, 6, 3) for b in r[i:i + 3][::-1]) + b"\0\0" for r in reversed(rows))
    bmp = (b"BM" + struct.pack("<IHHI", 14 + 40 + len(bmp_rows), 0, 0, 54) +
           struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(bmp_rows), 2835, 2835, 0, 0) + bmp_rows)
    gif = (b"GIF89a" + struct.pack("<HHBBB", 1, 1, 0x80, 0, 0) + bytes([0, 0, 0, 255, 255, 255]) +
           b"," + struct.pack("<HHHHB", 0, 0, 1, 1, 0) + bytes([2, 2, 0x44, 0x01, 0]) + b";")
    tga = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 2, 2, 24, 0x20) + b"".join(
        bytes(r[i:i + 3][::-1]) for r in rows for i in range(0, 6, 3))
    ppm = b"P6\n2 2\n255\n" + rgb
    planes = b"".join(bytes(rgb[p::3]) for p in range(3))
    psd = (b"8BPS" + struct.pack(">H6xHIIHH", 1, 3, 2, 2, 8, 3) + struct.pack(">III", 0, 0, 0) +
           struct.pack(">H", 0) + planes)
    hdr = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n" + bytes([128, 0, 0, 129] * 4)
    return [("red.hdr", hdr), ("rgb.bmp", bmp), ("one.gif", gif), ("rgb.tga", tga), ("rgb.ppm", ppm), ("rgb.psd", psd)]


def jpeg_corner(data, size=32, scan_bytes=4096):
    """The top-left size x size pixels of a baseline or progressive JPEG, without re-encoding: the frame header
    says the smaller size, the entropy-coded data is cut after `scan_bytes` (that corner's blocks come first),
    and an end-of-image marker follows. A 2048^2 texture decodes 20 times a second under the sanitizers."""
    pos = 2
    while pos + 4 <= len(data):
        marker, length = data[pos + 1], struct.unpack(">H", data[pos + 2:pos + 4])[0]
        if marker in (0xC0, 0xC1, 0xC2):
            data = data[:pos + 5] + struct.pack(">HH", size, size) + data[pos + 9:]
        if marker == 0xDA:
            return data[:pos + 2 + length + scan_bytes] + b"\xff\xd9"
        pos += 2 + length
    return data


def main():
    project, assets, out = (pathlib.Path(a) for a in sys.argv[1:4])
    scene_seeds(project, assets, out / "scene_json_fuzzer")
    gltf_seeds(project, assets, out / "gltf_fuzzer")
    hdr_seeds(assets, out / "radiance_hdr_fuzzer")
    texture_seeds(project, assets, out / "texture_fuzzer")


if __name__ == "__main__":
    main()
