"""The campaign's castle parts (prefabs.py), each written once as a sandbox scene in levels/parts/: what the
editor's Insert > Castle parts adds, and what a level generator builds from. tools/make-levels writes them and its
--check (ctest levels_match_generator) keeps them equal to what the prefabs make.

Each part stands on the ground at x = 0, as the campaign uses it; the editor moves a part to the pointer.
"""

from prefabs import Scene, ball, cage, castle, column, double_frame, fortress, frame, gate, keep, pyramid, roof, tnt, \
    tower


def _roofed_frame(s):
    roof(s, 0, frame(s, 0, 0, 2.0, 2.0, "wood", "wood", "small"), 2.6, "wood")


def _tnt_stack(s):
    top = frame(s, 0, 0, 1.6, 1.2, "wood", "wood", "small")
    tnt(s, 0, top, 0.6)


PARTS = [
    ("frame", "Frame: two wood posts and a plank over a small pig", lambda s: frame(s, 0, 0, 2.0, 2.0, "wood", "wood",
                                                                                     "small")),
    ("roofed-frame", "Frame under a gable roof", _roofed_frame),
    ("double-frame", "Double frame: three posts, two planks, two pigs",
     lambda s: double_frame(s, 0, 0, 2.0, 2.0, "wood", "wood", ("small", "medium"))),
    ("tower-3", "Tower of three wood frames, a pig on each storey",
     lambda s: tower(s, 0, 0, 3, 2.0, 2.0, ("wood",), ("wood",), ("small", "medium", "small"))),
    ("ice-tower-2", "Tower of two ice frames with wood planks",
     lambda s: tower(s, 0, 0, 2, 2.0, 2.0, ("ice",), ("wood",), ("small", "small"))),
    ("pyramid-3", "Pyramid of wood boxes, three rows", lambda s: pyramid(s, 0, 0, 3, 0.8, "wood")),
    ("column-4", "Column of four stone blocks", lambda s: column(s, 0, 0, 4, 0.8, 0.8, ("stone",))),
    ("cage", "Wood cage with a small pig inside", lambda s: cage(s, 0, 0, 1.2, "wood", "small")),
    ("boulder", "Stone boulder", lambda s: ball(s, 0, 0, 0.8, "stone")),
    ("tnt-on-frame", "TNT crate on a frame over a pig", _tnt_stack),
    ("gate", "Gate: two stone pillars under a wood lintel, a pig beneath",
     lambda s: gate(s, 0, 0, 3.0, 3, 0.6, "stone", "wood", "small")),
    ("castle", "Castle: a keep of three stone storeys between two towers, roofed",
     lambda s: castle(s, 0, 0, 3, "stone", "wood", ("medium", "small", "helmet"), "wood")),
    ("keep-2", "Keep: two storeys of two bays under one plank each",
     lambda s: keep(s, 0, 0, 2, 2.0, 3.0, "stone", "wood", ("small", "medium", "small", None))),
    ("fortress", "Fortress: a two-bay keep between two towers, cages in the gaps",
     lambda s: fortress(s, 0, 0, "stone", "wood", ("medium", "small"), ("small", "small"), "stone")),
]


def part(name, title, build):
    """The part as a sandbox scene (level JSON): no pig needed, never in a campaign."""
    s = Scene()
    build(s)
    body = {
        "$schema": "../schema/level.schema.json",
        "format": 1,
        "id": "part-" + name,
        "title": title,
        "sandbox": True,
        "slingshot": {"x": -15, "y": 1.5},
        "birds": ["red"],
        "blocks": s.blocks,
    }
    if s.pigs:
        body["pigs"] = s.pigs
    return body
