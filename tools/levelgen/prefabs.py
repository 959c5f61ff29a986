"""Reusable pieces of the campaign's structures.

Every piece is placed by the centre of its base and the height of what it stands on, and returns the height of its
own top, so pieces stack: `top = frame(scene, 20, 0); roof(scene, 20, top, 2.6)`. Each body rests exactly on the
surface under it (a block's centre is the surface plus half its height), which is what the rest check asks for.
Sizes follow the campaign's vocabulary: posts 0.25 m thick, planks 0.25 m thick and 0.6 m wider than the span
between their posts' centres, pigs of the catalog's radii.
"""

PIG_RADIUS = {"small": 0.25, "medium": 0.35, "large": 0.5, "helmet": 0.35}
POST = 0.25
PLANK = 0.25


def _n(value):
    """Numbers as the level files write them: no binary noise from the sums (0.1 + 0.2)."""
    rounded = round(value, 4)
    return int(rounded) if rounded == int(rounded) else rounded


class Scene:
    """The bodies of one level, in the order pieces add them."""

    def __init__(self):
        self.blocks = []
        self.pigs = []
        self.terrain = []

    def block(self, material, x, y, w, h=None, shape="box", angle=0, wall=None):
        body = {}
        if shape != "box":
            body["shape"] = shape
        body.update({"material": material, "x": _n(x), "y": _n(y), "w": _n(w)})
        if shape != "circle":
            body["h"] = _n(h)
        if angle:
            body["angle_deg"] = angle
        if wall is not None:
            body["wall"] = wall
        self.blocks.append(body)

    def pig(self, kind, x, surface):
        """A pig resting on the surface at height `surface`."""
        self.pigs.append({"type": kind, "x": _n(x), "y": _n(surface + PIG_RADIUS[kind])})

    def polygon(self, points):
        self.terrain.append({"points": [[_n(px), _n(py)] for px, py in points]})

    def slab(self, x, y, w, h):
        """A terrain box by its centre."""
        self.terrain.append({"x": _n(x), "y": _n(y), "w": _n(w), "h": _n(h)})


# Frames and towers ---------------------------------------------------------------------------------------------------


def frame(s, x, y, span=2.0, height=2.0, post="wood", plank="wood", pig=None):
    """Two posts and a plank across them; a pig between the posts if given. Returns the plank's top."""
    s.block(post, x - span / 2, y + height / 2, POST, height)
    s.block(post, x + span / 2, y + height / 2, POST, height)
    s.block(plank, x, y + height + PLANK / 2, span + 0.6, PLANK)
    if pig:
        s.pig(pig, x, y)
    return y + height + PLANK


def tower(s, x, y, storeys, span=2.0, height=2.0, posts=("wood",), planks=("wood",), pigs=()):
    """Frames stacked on each other; storey i uses posts[i % len], planks[i % len] and pigs[i] (None: empty)."""
    for i in range(storeys):
        pig = pigs[i] if i < len(pigs) else None
        y = frame(s, x, y, span, height, posts[i % len(posts)], planks[i % len(planks)], pig)
    return y


def double_frame(s, x, y, span=2.0, height=2.0, post="wood", plank="wood", pigs=(None, None)):
    """Three posts and two planks side by side: a frame of two bays, centre x. Returns the top."""
    for dx in (-span, 0, span):
        s.block(post, x + dx, y + height / 2, POST, height)
    for i, dx in enumerate((-span / 2, span / 2)):
        s.block(plank, x + dx, y + height + PLANK / 2, span - 0.02, PLANK)  # both rest on the middle post
        if pigs[i]:
            s.pig(pigs[i], x + dx, y)
    return y + height + PLANK


def roof(s, x, y, width, material="wood"):
    """A gable of two right triangles (their right angles at the middle). Returns the ridge height."""
    half = width / 2
    # A triangle has its right angle at the bottom left; turned 90 degrees it is at the bottom right.
    s.block(material, x - half / 2, y + half / 2, half, half, shape="triangle", angle=90)
    s.block(material, x + half / 2, y + half / 2, half, half, shape="triangle")
    return y + half


def pyramid(s, x, y, rows, size=0.8, material="wood", gap=0.0):
    """Square blocks, `rows` at the bottom and one fewer on each course above. Returns the top."""
    for row in range(rows):
        count = rows - row
        for i in range(count):
            bx = x + (i - (count - 1) / 2) * (size + gap)
            s.block(material, bx, y + size / 2, size, size)
        y += size
    return y


def column(s, x, y, courses, w=0.8, h=0.8, materials=("stone",)):
    """Blocks stacked one on another. Returns the top."""
    for i in range(courses):
        s.block(materials[i % len(materials)], x, y + h / 2, w, h)
        y += h
    return y


def cage(s, x, y, size=1.2, material="wood", pig="small", wall=0.1):
    """A hollow box with a pig sitting inside it. Returns its top."""
    s.block(material, x, y + size / 2, size, size, shape="hollow_box", wall=wall)
    if pig:
        s.pig(pig, x, y + wall)
    return y + size


def ball(s, x, y, diameter=0.8, material="stone"):
    s.block(material, x, y + diameter / 2, diameter, shape="circle")
    return y + diameter


def tnt(s, x, y, size=0.6):
    s.block("tnt", x, y + size / 2, size, size)
    return y + size


def gate(s, x, y, span=3.0, courses=3, size=0.6, pillar="stone", lintel="wood", pig=None):
    """Two square pillars and a lintel: an opening a bird can fly through. Returns the lintel's top."""
    half = span / 2
    column(s, x - half, y, courses, size, size, (pillar,))
    column(s, x + half, y, courses, size, size, (pillar,))
    top = y + courses * size
    s.block(lintel, x, top + PLANK / 2, span + size + 0.2, PLANK)
    if pig:
        s.pig(pig, x, y)
    return top + PLANK


def castle(s, x, y, keep_storeys=3, material="stone", planks="wood", pigs=("medium", "small", "helmet"),
           roof_mat="wood"):
    """A keep of stacked frames between two lower towers, each crowned by a roof: the genre's fortress."""
    top = tower(s, x, y, keep_storeys, 2.0, 2.0, (material,), (planks,), pigs)
    roof(s, x, top, 2.6, roof_mat)
    for side in (-1, 1):
        t = tower(s, x + side * 3.4, y, keep_storeys - 1, 1.6, 2.0, (material,), (planks,),
                  ("small",) if keep_storeys > 1 else ())
        roof(s, x + side * 3.4, t, 2.2, roof_mat)
    return top


def keep(s, x, y, storeys, bay=2.0, height=3.0, post="stone", plank="wood", pigs=()):
    """Storeys of three posts under one plank: two bays side by side; storey i's pigs are pigs[2i] (left bay) and
    pigs[2i + 1] (right bay), None for an empty bay. Returns the top. (double_frame's two planks end short of its
    outer posts, so a storey cannot stand on it.)"""
    for i in range(storeys):
        for dx in (-bay, 0, bay):
            s.block(post, x + dx, y + height / 2, POST, height)
        s.block(plank, x, y + height + PLANK / 2, 2 * bay + 0.6, PLANK)
        for j, dx in enumerate((-bay / 2, bay / 2)):
            pig = pigs[2 * i + j] if 2 * i + j < len(pigs) else None
            if pig:
                s.pig(pig, x + dx, y)
        y += height + PLANK
    return y


def fortress(s, x, y, material="stone", planks="wood", keep_pigs=(), side_pigs=("small", "small"), roof_mat="stone",
             height=3.0):
    """A keep of two bays and two tall storeys between two one-storey towers, each under a roof, and an empty cage
    in each gap: a castle as wide as a tall one but never more than five bodies deep, so Box2D solves it in one
    step (GameWorld's stack sub-steps start at six). Returns the keep's top."""
    top = keep(s, x, y, 2, 2.0, height, material, planks, keep_pigs)
    roof(s, x, top, 3.0, roof_mat)
    for side in (-1, 1):  # merlons beside the roof
        s.block(material, x + side * 1.95, top + 0.25, 0.5, 0.5)
    for side, pig in zip((-1, 1), side_pigs):
        t = frame(s, x + side * 4.4, y, 1.6, height, material, planks, pig)
        roof(s, x + side * 4.4, t, 2.2, roof_mat)
        cage(s, x + side * 2.8, y, 0.8, "wood", None)
    return top


# Terrain -------------------------------------------------------------------------------------------------------------


def hill(s, x0, x1, height, plateau=0.5, ground=0.0):
    """A hill from x0 to x1 with a flat top of `plateau` times its width. Returns (left, right) ends of the top."""
    width = x1 - x0
    left = x0 + width * (1 - plateau) / 2
    right = x1 - width * (1 - plateau) / 2
    s.polygon([(x0, ground), (x1, ground), (right, ground + height), (left, ground + height)])
    return left, right


def island(s, x, y, width, depth=1.5):
    """A floating island: flat top at height y, a rocky underside tapering down. Returns its top."""
    half = width / 2
    s.polygon([(x - half, y), (x - half + 0.5, y - depth * 0.6), (x, y - depth), (x + half - 0.5, y - depth * 0.6),
               (x + half, y)])
    return y


def plateau(s, x0, x1, height, ground=0.0):
    """A flat-topped cliff with vertical sides. Returns its top."""
    s.polygon([(x0, ground), (x1, ground), (x1, ground + height), (x0, ground + height)])
    return ground + height
