#!/usr/bin/env python3
"""Golden motion images for the project's example motions, made independently of the TypeScript encoder.

Reads each .rbm file as text (docs/protocol.md section 7) and builds its motion image from the table of
section 6.3, with nothing but the Python standard library: it shares no code with src/protocol/motion-image.ts,
so a mistake in either shows up as a difference in tests/unit/motion-image.test.ts.

    python3 tests/data/make-golden-images.py                  # examples/*.rbm -> tests/data/images/<name>.img.hex
    python3 tests/data/make-golden-images.py --check A.rbm B.img.hex   # compare one file with a given image

For each file it prints what the tests pin as literals: the image size, the XOR checksum of each 64-byte
download chunk, the 14-byte first part of the download (section 6.2) and the memory the file takes (section 6.1:
size + 64 - size mod 64), with the free motion memory left after it on an empty robot (24,576 bytes).
"""

import pathlib
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
IMAGES = ROOT / "tests" / "data" / "images"
MOTION_AREA = 0x6000
HEADER = bytes.fromhex("FFFFAA55AA5537BA")


def read_rbm(text):
    """The fields of an .rbm text as numbers where the image needs them (section 7)."""
    fields = text.rstrip(" \t\r\n").split(":")
    if fields[-1] != "":
        raise ValueError("an .rbm file ends with ':'")
    fields = fields[:-1]
    scene_count = int(fields[9])
    servo_count = int(fields[11])
    expected = 13 + 6 * servo_count + scene_count * (5 + 6 * servo_count)
    if len(fields) != expected:
        raise ValueError("%d fields, expected %d" % (len(fields), expected))
    motion = {
        "motion_index": int(fields[7]),
        "platform": int(fields[8]),
        "servos": [],
        "scenes": [],
    }
    at = 13
    for _ in range(servo_count):
        servo_id, p, d, i, port_enable, zero = (int(x) for x in fields[at : at + 6])
        motion["servos"].append((servo_id, p, d, i, port_enable, zero))
        at += 6
    for _ in range(scene_count):
        index = int(fields[at])
        frames = int(fields[at + 3])
        time_ms = int(fields[at + 4])
        at += 5
        records = []
        for _ in range(servo_count):
            _reserved, servo_id, start, end, torque, port = (int(x) for x in fields[at : at + 6])
            records.append((servo_id, start, end, torque, port))
            at += 6
        motion["scenes"].append((index, frames, time_ms, records))
    return motion


def motion_image(motion):
    """Section 6.3: little-endian, only the file's W servos."""
    servo_count = len(motion["servos"])
    scene_count = len(motion["scenes"])
    size = 12 + 6 * servo_count + scene_count * (6 + 5 * servo_count)
    out = bytearray()
    out += struct.pack("<BBIHH", motion["platform"], motion["motion_index"], 0, scene_count, servo_count)
    for servo in motion["servos"]:
        out += struct.pack("<6B", *servo)
    out += struct.pack("<H", size)
    for index, frames, time_ms, records in motion["scenes"]:
        out += struct.pack("<HHH", index, frames, time_ms)
        for record in records:
            out += struct.pack("<5B", *record)
    if len(out) != size:
        raise AssertionError("image is %d bytes, the table says %d" % (len(out), size))
    return bytes(out)


def hex_lines(data):
    """16 bytes a line, uppercase, one space between bytes, a newline after every line."""
    return "".join(" ".join("%02X" % b for b in data[o : o + 16]) + "\n" for o in range(0, len(data), 16))


def describe(name, image):
    size = len(image)
    chunks = [image[o : o + 64] for o in range(0, size, 64)]
    checksums = []
    for chunk in chunks:
        x = 0
        for b in chunk:
            x ^= b
        checksums.append(x)
    first_part = HEADER + bytes([0x01, 0x00]) + struct.pack(">I", size)
    footprint = size + 64 - size % 64
    print(name)
    print("  image size:      %d bytes, %d chunks (last %d bytes)" % (size, len(chunks), len(chunks[-1])))
    print("  chunk checksums: %s" % " ".join("%02X" % c for c in checksums))
    print("  first part:      %s" % " ".join("%02X" % b for b in first_part))
    free = MOTION_AREA - footprint
    print("  memory:          %d bytes; free motion memory after it: %d = %s" % (
        footprint,
        free,
        " ".join("%02X" % b for b in struct.pack(">i", free)) if free >= 0 else "(does not fit)",
    ))


def main(argv):
    if len(argv) == 4 and argv[1] == "--check":
        image = motion_image(read_rbm(pathlib.Path(argv[2]).read_text(encoding="latin-1")))
        golden = pathlib.Path(argv[3]).read_text(encoding="ascii")
        describe(argv[2], image)
        same = hex_lines(image) == golden
        print("  identical to %s: %s" % (argv[3], "yes" if same else "NO"))
        return 0 if same else 1
    IMAGES.mkdir(parents=True, exist_ok=True)
    for path in sorted(EXAMPLES.glob("*.rbm")):
        image = motion_image(read_rbm(path.read_text(encoding="latin-1")))
        target = IMAGES / (path.stem + ".img.hex")
        target.write_text(hex_lines(image), encoding="ascii", newline="\n")
        describe("examples/%s -> tests/data/images/%s" % (path.name, target.name), image)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
