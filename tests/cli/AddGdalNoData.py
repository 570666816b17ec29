# SPDX-License-Identifier: BSD-3-Clause
"""AddGdalNoData.py IN.tif OUT.tif VALUE: IN with GDAL's no-data tag (42113, GDAL_NODATA, ASCII)
added to its first directory, as GDAL writes it in a DEM; VALUE is written as given.

The directory is rewritten at the end of the file with the tag in its sorted place; every other
byte, and every offset the old entries hold, stays as it was. Classic TIFF, either byte order."""
import struct
import sys

GDAL_NODATA = 42113
ASCII = 2


def main(source, target, value):
    data = bytearray(open(source, "rb").read())
    order = {b"II": "<", b"MM": ">"}[bytes(data[:2])]
    if struct.unpack(order + "H", data[2:4])[0] != 42:
        sys.exit(f"{source}: not a classic TIFF")
    ifd = struct.unpack(order + "I", data[4:8])[0]
    count = struct.unpack(order + "H", data[ifd:ifd + 2])[0]
    entries = [bytes(data[ifd + 2 + 12 * k: ifd + 14 + 12 * k]) for k in range(count)]
    following = data[ifd + 2 + 12 * count: ifd + 6 + 12 * count]
    entries = [e for e in entries if struct.unpack(order + "H", e[:2])[0] != GDAL_NODATA]

    text = value.encode("ascii") + b"\0"
    if len(data) % 2:
        data += b"\0"
    new_ifd = len(data)
    text_offset = new_ifd + 2 + 12 * (len(entries) + 1) + 4
    if len(text) <= 4:
        inline = text.ljust(4, b"\0")
    else:
        inline = struct.pack(order + "I", text_offset)
    entries.append(struct.pack(order + "HHI", GDAL_NODATA, ASCII, len(text)) + inline)
    entries.sort(key=lambda e: struct.unpack(order + "H", e[:2])[0])

    data += struct.pack(order + "H", len(entries)) + b"".join(entries) + following
    if len(text) > 4:
        data += text
    data[4:8] = struct.pack(order + "I", new_ifd)
    open(target, "wb").write(data)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
