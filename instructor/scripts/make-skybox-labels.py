"""Writes scenes/skybox_labels/{right,left,top,bottom,front,back}.png: one colour
per face, its name in large letters, an arrow towards the picture's top and the
axis the face is seen along, so a render shows which picture a direction sees.

    python3 instructor/scripts/make-skybox-labels.py
"""
import struct
import zlib

# 5 x 7 capital letters, signs and digits, one string of 5 characters a row ('#' = ink).
GLYPHS = {
    "A": [" ### ", "#   #", "#   #", "#####", "#   #", "#   #", "#   #"],
    "B": ["#### ", "#   #", "#   #", "#### ", "#   #", "#   #", "#### "],
    "C": [" ####", "#    ", "#    ", "#    ", "#    ", "#    ", " ####"],
    "E": ["#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#####"],
    "F": ["#####", "#    ", "#    ", "#### ", "#    ", "#    ", "#    "],
    "G": [" ####", "#    ", "#    ", "#  ##", "#   #", "#   #", " ####"],
    "H": ["#   #", "#   #", "#   #", "#####", "#   #", "#   #", "#   #"],
    "I": ["#####", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", "#####"],
    "K": ["#   #", "#  # ", "# #  ", "##   ", "# #  ", "#  # ", "#   #"],
    "L": ["#    ", "#    ", "#    ", "#    ", "#    ", "#    ", "#####"],
    "M": ["#   #", "## ##", "# # #", "#   #", "#   #", "#   #", "#   #"],
    "N": ["#   #", "##  #", "# # #", "#  ##", "#   #", "#   #", "#   #"],
    "O": [" ### ", "#   #", "#   #", "#   #", "#   #", "#   #", " ### "],
    "P": ["#### ", "#   #", "#   #", "#### ", "#    ", "#    ", "#    "],
    "R": ["#### ", "#   #", "#   #", "#### ", "# #  ", "#  # ", "#   #"],
    "T": ["#####", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  "],
    "X": ["#   #", "#   #", " # # ", "  #  ", " # # ", "#   #", "#   #"],
    "Y": ["#   #", "#   #", " # # ", "  #  ", "  #  ", "  #  ", "  #  "],
    "Z": ["#####", "    #", "   # ", "  #  ", " #   ", "#    ", "#####"],
    "+": ["     ", "  #  ", "  #  ", "#####", "  #  ", "  #  ", "     "],
    "-": ["     ", "     ", "     ", "#####", "     ", "     ", "     "],
    "^": ["  #  ", " ### ", "# # #", "  #  ", "  #  ", "  #  ", "  #  "],
}

SIZE = 128
FACES = [  # name, what it is seen along, background colour (0..255)
    ("right", "-X", (200, 60, 60)),
    ("left", "+X", (60, 160, 60)),
    ("top", "+Y", (70, 110, 210)),
    ("bottom", "-Y", (200, 170, 40)),
    ("front", "+Z", (160, 70, 190)),
    ("back", "-Z", (40, 170, 180)),
]


def draw_text(pixels, text, centre_x, top, scale, ink):
    width = len(text) * 6 * scale - scale
    left = centre_x - width // 2
    for i, char in enumerate(text):
        rows = GLYPHS[char]
        for gy, row in enumerate(rows):
            for gx, cell in enumerate(row):
                if cell != "#":
                    continue
                for dy in range(scale):
                    for dx in range(scale):
                        x = left + (i * 6 + gx) * scale + dx
                        y = top + gy * scale + dy
                        if 0 <= x < SIZE and 0 <= y < SIZE:
                            pixels[y][x] = ink


def write_png(path, pixels):
    raw = b"".join(b"\x00" + bytes(value for pixel in row for value in pixel) for row in pixels)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


for name, axis, colour in FACES:
    pixels = [[colour for _ in range(SIZE)] for _ in range(SIZE)]
    for i in range(SIZE):  # a white frame shows where faces meet
        for j in (0, 1, SIZE - 2, SIZE - 1):
            pixels[i][j] = pixels[j][i] = (255, 255, 255)
    draw_text(pixels, "^", SIZE // 2, 10, 3, (255, 255, 255))  # towards the picture's top row
    draw_text(pixels, name.upper(), SIZE // 2, 52, 3 if len(name) <= 5 else 2, (255, 255, 255))
    draw_text(pixels, axis, SIZE // 2, 88, 3, (20, 20, 20))
    write_png(f"scenes/skybox_labels/{name}.png", pixels)
