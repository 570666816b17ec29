# SPDX-License-Identifier: BSD-3-Clause
"""WriteSrtmTile.py OUT.hgt SIDE voids|filled: an SRTM height tile (SIDE x SIDE big-endian int16
metres, the northernmost row first, no header) of rolling terrain from -20 to 480 m with voids
(-32768) in two blocks, or with those texels at the tile's lowest height instead ("filled")."""
import math
import struct
import sys


def heights(side):
    rows = []
    for r in range(side):
        row = []
        for i in range(side):
            x, y = i / (side - 1), r / (side - 1)
            row.append(round(230 + 250 * math.sin(5 * x + 1) * math.cos(4 * y)))
        rows.append(row)
    return rows


def main(target, side, mode):
    side = int(side)
    rows = heights(side)
    low = min(min(row) for row in rows)
    for r in range(side):
        for i in range(side):
            void = (r < side // 4 and i < side // 3) or (r > side // 2 and side // 2 < i < side // 2 + 5)
            if void:
                rows[r][i] = -32768 if mode == "voids" else low
    with open(target, "wb") as out:
        for row in rows:
            out.write(struct.pack(">%dh" % side, *row))


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[3] not in ("voids", "filled"):
        sys.exit(__doc__)
    main(*sys.argv[1:])
