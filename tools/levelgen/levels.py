"""The campaign's levels built from prefabs: each function returns one level (its fields but stars, which
tools/balance-campaign sets from the model player). Levels of the first round that are not here are hand-written."""

from prefabs import (Scene, ball, cage, castle, column, double_frame, fortress, frame, gate, hill, island, plateau,
                     pyramid, roof, tnt, tower)

EARTH_AIR = 1.2
# On the Moon the arcs stay long and slow, but a full pull still breaks wood: the red bird leaves at 17.5 m/s
# (70 N s against wood's 60), a quarter of the pull is enough for the nearest towers.
MOON_SLINGSHOT = {"x": 0, "y": 1.5}  # the Moon's band: the catalog's


def claim_form(what):
    """A claim's key: a comparison ("holds"), a material no shot breaks ("cannot_break") or an outcome."""
    if isinstance(what, str):
        return "holds"
    return "cannot_break" if "material" in what else "outcome"


def level(id_, title, concept, hints, birds, scene, reference_shot, slingshot=None, environment=None, theme=None,
          extra=None, claims=None):
    body = {
        "$schema": "schema/level.schema.json",
        "format": 1,
        "id": id_,
        "title": title,
        "episode": id_.split("-")[0],
        "concept": concept,
        "hints": hints,
        # A claim is (about, "comparison") or (about, {outcome}) (levels/README.md, "Claims").
        **({"claims": [{"about": about, claim_form(what): what} for about, what in claims]} if claims else {}),
        "slingshot": slingshot or {"x": 0, "y": 1.5},
        "birds": birds,
        "blocks": scene.blocks,
        "pigs": scene.pigs,
    }
    if scene.terrain:
        body["terrain"] = scene.terrain
    if environment:
        body["environment"] = environment
    if theme:
        body["theme"] = theme
    if extra:
        body.update(extra)
    body["stars"] = [10000, 20000, 30000]
    body["reference_shot"] = list(reference_shot)
    return body


# Episode 1: launch angle and range -----------------------------------------------------------------------------------


def l1_6():
    s = Scene()
    top = pyramid(s, 30, 0, 5, 0.8, "wood")
    s.pig("medium", 30, top)
    s.pig("small", 26.8, 0)
    s.pig("small", 33.2, 0)
    roof(s, 26.8 - 1.2, 0, 1.2, "ice")
    roof(s, 33.2 + 1.2, 0, 1.2, "ice")
    ball(s, 36.2, 0, 0.8, "wood")
    return level("1-5", "Pyramid Point",
                 "In vacuum a bird launched at {v_max:red} m/s at angle theta lands v0^2 sin(2 theta) / g away on "
                 "level ground: at most {range_flat:red} m, at 45 degrees. The pyramid is much nearer: pull "
                 "less, or take a flatter or a steeper angle of the same range.",
                 ["The pyramid's top pig is the highest: a flat shot at the upper courses pushes it off."],
                 ["red", "red", "red"], s, (40.0, 18))


def l1_7():
    s = Scene()
    castle(s, 40, 0, 3, "wood", "wood", ("medium", None, "small"), "ice")
    cage(s, 45.4, 0, 1.2, "ice", "small")
    return level("1-4", "Castle on the Plain",
                 "Two launch angles reach the same range, theta and 90 - theta, in vacuum. The flat one is quick and "
                 "strikes the walls; the steep one drops onto the roofs from above.",
                 ["Try the steep shot: the roofs are ice."],
                 ["red", "red", "red", "red"], s, (30.0, 24.0))


def l1_8():
    s = Scene()
    column(s, 22, 0, 5, 0.8, 0.8, ("stone",))
    column(s, 22.8, 0, 5, 0.8, 0.8, ("stone",))
    cage(s, 27, 0, 1.2, "wood", "medium")
    cage(s, 29, 0, 1.2, "wood", "small")
    top = frame(s, 28, 1.2, 2.0, 1.6, "wood", "wood", None)
    roof(s, 28, top, 2.6, "wood")
    return level("1-7", "Over the Wall",
                 "A stone wall stands between you and the pigs. Only a high arc clears it: above 45 degrees the "
                 "bird climbs steeply and comes down steeply behind it.",
                 ["Aim high and pull less: the bird drops behind the wall."],
                 ["red", "red", "red", "red"], s, (62.5, 18))


# Episode 2: heavy and light birds, momentum --------------------------------------------------------------------------


def l2_6():
    s = Scene()
    # The hilltop ends just past the frame's last post and its right side falls steeply, 3 m over 4.7 m: a boulder
    # that leaves the top rolls down it into the tower. Each boulder rests near its plank's right end, so the black
    # bird's blast from the left sends it over the edge.
    s.polygon([(16, 0), (29, 0), (24.3, 3.0), (19, 3.0)])
    double_frame(s, 22, 3.0, 2.0, 1.6, "wood", "wood", ("small", "medium"))
    ball(s, 21.6, 3.0 + 1.6 + 0.25, 0.8, "stone")
    ball(s, 23.6, 3.0 + 1.6 + 0.25, 0.8, "stone")
    top = tower(s, 31, 0, 2, 2.0, 2.0, ("wood",), ("wood",), ("large", "helmet"))
    roof(s, 31, top, 2.6, "wood")
    pyramid(s, 35.5, 0, 3, 0.7, "wood")
    s.pig("small", 35.5, 2.1)
    return level("2-3", "Boulder Hill",
                 "A heavy ball keeps its momentum: the {mass:black} kg black bird leaves the band at {v_max:black} m/s "
                 "with p = {p_max:black} N s, more than the red bird's {p_max:red} N s, and pushes the boulders on "
                 "the hill over the edge. Rolling down they gain speed from their height and crush what is below. "
                 "The boulders are solid granite, not masonry: they take {strength:stone} N s before they break, so "
                 "they survive the fall.",
                 ["Knock the boulders off the hilltop: they roll into the tower below."],
                 ["black", "red", "black", "red"], s, (12.0, 22.0),
                 # A 120 kg boulder dropping 1.8 m takes about 760 N s: the castle stone's 300 would shatter it.
                 extra={"materials": {"stone": {"strength_ns": 2000}}},
                 # The right boulder (x 23.6) defeats a pig of the tower (x 31) in 8 of the 9 aims.
                 claims=[("/hints/0", {"shot": [12.0, 22.0], "pig_x": [30.5, 31.5], "by_block_x": [23.55, 23.65],
                                       "in_at_least": 7})])


def l2_7():
    s = Scene()
    gate(s, 22, 0, 2.4, 4, 0.6, "stone", "wood", None)
    cage(s, 22, 0, 1.2, "wood", "small")
    castle(s, 31, 0, 2, "wood", "wood", ("large", "small"), "wood")
    tnt(s, 31.55, 2.25, 0.5)
    return level("2-4", "Stone Gate",
                 "The same pull sends every bird off at nearly the same speed: the {mass:black} kg black bird leaves at "
                 "{v_max:black} m/s and takes the biggest share of the band's {energy} J, {share:black} %. It carries "
                 "the most momentum, p = m v0 = {p_max:black} N s: what it hits, moves.",
                 ["The gate's pillars are stone: send the heavy bird at them, or fly over to the castle."],
                 ["black", "black", "red", "red"], s, (17.5, 21.21))


def l2_8():
    s = Scene()
    # Tall stone towers closer together than they are tall: one pushed high tips about its foot onto the next. The
    # pigs on the plinths are what a falling tower lands on; the ones in the wood frames between are for the next birds.
    s.block("stone", 18, 3, 0.3, 6)
    roof(s, 19.75, frame(s, 19.75, 0, 1.6, 1.2, "wood", "wood", "medium"), 1.6, "wood")
    s.block("stone", 21.5, 2.25, 0.6, 4.5)
    s.pig("small", 21.5, 4.5)
    ball(s, 23.3, 0, 0.6, "stone")
    s.block("stone", 25, 3, 0.3, 6)
    roof(s, 26.75, frame(s, 26.75, 0, 1.6, 1.2, "wood", "wood", "medium"), 1.6, "wood")
    s.block("stone", 28.5, 2.25, 0.6, 4.5)
    s.pig("small", 28.5, 4.5)
    roof(s, 31, frame(s, 31, 0, 1.6, 1.2, "wood", "ice", "small"), 1.6, "ice")
    s.pig("small", 34, pyramid(s, 34, 0, 3, 0.8, "wood"))
    return level("2-6", "Wrecking Crew",
                 "A tall tower tips when it is pushed high up: the push turns it about its foot, and once its centre "
                 "of mass passes over the edge gravity does the rest. These towers stand closer together than they "
                 "are tall, so the first one to fall lands on the next. The bird only has to start it.",
                 ["Hit the first tower high up: it falls onto the next."],
                 ["red", "red", "blue", "red"], s, (16.0, 28.0),
                 claims=[("/hints/0", {"shot": [16.0, 28.0], "pig_x": [21.0, 22.0], "by_block_x": [17.5, 18.5],
                                       "in_at_least": 7})])


# Episode 3: air and wind ----------------------------------------------------------------------------------------------


def l3_6():
    s = Scene()
    hill(s, 28, 46, 4.0, 0.6)
    castle(s, 37, 4.0, 2, "wood", "wood", ("medium", "small"), "ice")
    pyramid(s, 24.5, 0, 3, 0.7, "wood")
    s.pig("large", 26.5, 0)
    return level("3-7", "Windy Ridge",
                 "Drag pulls the bird towards the wind's velocity: F = -1/2 rho Cd A |v - w| (v - w). With {wind} "
                 "m/s at its back the red bird carries farther than in still air ({best_range:red} m against "
                 "{calm_best_range:red} m at full pull), over the ridge to the castle.",
                 ["The tailwind adds range, most to high, slow shots that ride it longest: the farthest shot "
                  "leaves at {best_angle:red} degrees, against {calm_best_angle:red} in still air."],
                 ["red", "red", "red", "red"], s, (30.0, 27.0), environment={"air_density": EARTH_AIR, "wind": [8, 0]},
                 claims=[("/concept", "best_range:red > calm_best_range:red"),
                         ("/hints/0", "best_angle:red > calm_best_angle:red")])


def l3_7():
    s = Scene()
    pyramid(s, 22, 0, 4, 0.7, "wood")
    s.pig("small", 22, 2.8)
    cage(s, 25.5, 0, 1.2, "ice", "medium")
    top = tower(s, 29, 0, 3, 2.0, 2.0, ("wood", "ice"), ("wood",), ("large", "small", "helmet"))
    roof(s, 29, top, 2.6, "ice")
    tnt(s, 32.2, 0)
    return level("3-6", "Storm Front",
                 "Into a headwind of {wind} m/s the air's drag acts on the bird's speed relative to the wind, "
                 "which is higher than its ground speed: the bird slows sooner and falls short. Pull harder, and "
                 "aim a little lower than in still air: a high, slow shot stays longest in the wind.",
                 ["The wind blows against you: every shot falls shorter than in still air."],
                 ["red", "yellow", "red"], s, (47.5, 30), environment={"air_density": EARTH_AIR, "wind": [-8, 0]},
                 claims=[("/concept", "best_angle:red < calm_best_angle:red"),
                         ("/hints/0", "best_range:red < calm_best_range:red")])


def l3_8():
    s = Scene()
    island(s, 22, 5.0, 5.0)
    top = frame(s, 22, 5.0, 2.0, 1.6, "wood", "wood", "medium")
    roof(s, 22, top, 2.6, "wood")
    island(s, 32, 8.0, 6.0)
    top = tower(s, 32, 8.0, 2, 2.0, 1.6, ("wood",), ("wood",), ("small", "helmet"))
    roof(s, 32, top, 2.6, "ice")
    cage(s, 21, 0, 1.2, "wood", "small")
    cage(s, 23, 0, 1.2, "wood", "small")
    pyramid(s, 30, 0, 3, 0.7, "wood")
    cage(s, 34, 0, 1.4, "ice", "large")
    return level("3-8", "Sky Islands",
                 "Gusts change the wind during the flight: from {gust_t:1} s after launch the wind is {gust_wx:1} m/s, "
                 "from {gust_t:2} s {gust_wx:2} m/s. A bird feels them through drag, so the late part of a long "
                 "flight bends most.",
                 ["Short flights feel the gusts least: hit the low island first."],
                 ["red", "blue", "yellow", "red", "red"], s, (27.5, 30),
                 environment={"air_density": EARTH_AIR,
                              "gusts": [{"t": 1.0, "wx": 6, "wy": 0}, {"t": 2.0, "wx": -6, "wy": 0}]})


# Episode 4: materials -------------------------------------------------------------------------------------------------


def l4_6():
    s = Scene()
    top = tower(s, 24, 0, 4, 2.0, 1.6, ("ice",), ("wood",), ("medium", "small", "large", "small"))
    roof(s, 24, top, 2.6, "ice")
    double_frame(s, 30, 0, 2.0, 1.6, "ice", "ice", ("helmet", "small"))
    roof(s, 29, 1.85, 1.6, "ice")
    roof(s, 31, 1.85, 1.6, "ice")
    ball(s, 19.5, 0, 0.8, "ice")
    return level("4-6", "Glass House",
                 "Ice is light ({density:ice} kg/m^3) and brittle: {strength:ice} N s breaks a block, against "
                 "{strength:wood} N s for wood. The small blue birds split into a flock and shatter ice that a red "
                 "bird only pushes.",
                 ["Split the blue bird just before it reaches the ice (click in flight)."],
                 ["blue", "blue", "red"], s, (2.5, 32.32))


def l4_7():
    s = Scene()
    hill(s, 18, 24, 1.5, 0.4)
    top = double_frame(s, 28, 0, 2.2, 1.6, "wood", "wood", ("small", "medium"))
    tnt(s, 24.8, 0)
    tnt(s, 31.2, 0)
    frame(s, 28, top, 2.0, 1.6, "wood", "wood", "helmet")
    tnt(s, 33, 0)
    top = tower(s, 35, 0, 2, 2.0, 1.6, ("stone",), ("wood",), ("large", "small"))
    roof(s, 35, top, 2.6, "wood")
    ball(s, 37.5, 0, 0.8, "stone")
    return level("4-4", "Powder Store",
                 "TNT crates break at only {strength:tnt} N s and explode: everything near it gets a push and "
                 "damage that falls off with distance. One crate that goes off sets off its neighbours.",
                 ["Hit a crate: the blast does the rest."],
                 ["red", "red"], s, (20.0, 22.0))


def l4_8():
    s = Scene()
    castle(s, 28, 0, 3, "stone", "wood", ("helmet", "large", "helmet"), "stone")
    cage(s, 22.4, 0, 1.0, "wood", "small")
    cage(s, 33.6, 0, 1.0, "wood", "small")
    return level("4-5", "Stone Fortress",
                 "Stone is heavy ({density:stone} kg/m^3) and tough: it takes {strength:stone} N s to break, more "
                 "than a red bird at full speed carries ({p_max:red} N s). Knock the walls over and let their "
                 "weight fall on the pigs, or tap the black bird beside them: its blast breaks stone.",
                 ["A hit seldom breaks stone: hit the top of the keep so it topples."],
                 ["black", "black", "red", "yellow", "red"], s, (60.0, 19.09),
                 claims=[("/concept", "p_max:red < strength:stone")])


# Episode 5: other worlds and the clock -------------------------------------------------------------------------------


def l5_6():
    s = Scene()
    hill(s, 26, 30, 1.2, 0.3)
    hill(s, 42, 46, 1.2, 0.3)
    castle(s, 36, 0, 3, "wood", "wood", ("large", "small", "helmet"), "stone")
    cage(s, 44, 1.2, 1.0, "wood", None)
    return level("5-3", "Lunar Base",
                 "On the Moon g = {g} m/s^2: a bird at {v_max:red} m/s flies {earth_g / g|1} times as far and as long "
                 "as on Earth, and a falling block lands slowly, so a tower topples in slow motion.",
                 ["Gentle pulls go a long way here."],
                 ["red", "red", "red", "black", "red"], s, (15.0, 15.75), slingshot=MOON_SLINGSHOT,
                 environment={"gravity": 1.62}, theme="moon")


def l5_7():
    s = Scene()
    plateau(s, 20, 27, 3.0)
    plateau(s, 31, 40, 3.0)
    cage(s, 28.2, 0, 1.2, "wood", "large")
    cage(s, 29.8, 0, 1.2, "wood", None)
    top = tower(s, 23.5, 3.0, 2, 2.0, 1.6, ("wood",), ("wood",), ("small", "medium"))
    roof(s, 23.5, top, 2.6, "wood")
    top = tower(s, 35.5, 3.0, 2, 2.0, 1.6, ("wood",), ("wood",), ("helmet", "small"))
    roof(s, 35.5, top, 2.6, "wood")
    ball(s, 27.3 - 0.9, 3.0, 0.6, "stone")
    pyramid(s, 21.0, 3.0, 2, 0.5, "wood")
    return level("5-7", "Red Canyon",
                 "Mars: g = {g} m/s^2 and thin air ({rho} kg/m^3). At the same speed a bird stays up "
                 "{earth_g / g|1} times as long as on Earth, long enough to drop into the canyon between the cliffs.",
                 ["Drop a bird into the canyon, or push the boulder over its edge."],
                 ["red", "black", "red", "red"], s, (60.0, 12.5), slingshot={"x": 0, "y": 1.5},
                 environment={"gravity": 3.71, "air_density": 0.02}, theme="mars")


def l5_8():
    s = Scene()
    castle(s, 30, 0, 2, "stone", "wood", ("helmet", "large"), "wood")
    tnt(s, 25.3, 0)
    cage(s, 24.0, 0, 1.0, "wood", "small")
    pyramid(s, 36, 0, 3, 0.7, "wood")
    s.pig("medium", 36, 2.1)
    return level("5-4", "Jovian Keep",
                 "On Jupiter g = {g} m/s^2, {g / earth_g|1} times Earth's: even a {v_max:red} m/s bird falls fast, "
                 "and a block that tips comes down hard. The flight is short: {best_range:red} m at most for the "
                 "red bird.",
                 ["Gravity pulls the bird down quickly, but the best angle is still about {best_angle:red} "
                  "degrees: pull hard."],
                 ["red", "red", "black", "red"], s, (7.5, 50), slingshot={"x": 0, "y": 1.5},
                 environment={"gravity": 24.79, "air_density": 0.16}, theme="jupiter")


# Episode 6: castles and fortresses -----------------------------------------------------------------------------------


def l6_1():
    s = Scene()
    gate(s, 22, 0, 2.4, 3, 0.6, "stone", "wood", None)
    cage(s, 22, 0, 1.2, "wood", "medium")
    castle(s, 31, 0, 3, "wood", "wood", ("large", "small", "helmet"), "wood")
    tnt(s, 31.55, 2.25, 0.5)
    return level("6-7", "Gatehouse",
                 "Everything together: the launch angle sets the range, the bird's mass its momentum, the materials "
                 "how the castle breaks. A flat shot meets the gate; a steep one falls into the keep.",
                 ["The TNT in the keep's first floor brings the keep down."],
                 ["red", "black", "red", "red"], s, (47.5, 18))


def l6_2():
    s = Scene()
    hill(s, 26, 38, 1.0, 0.8)
    top = tower(s, 28.5, 1.0, 3, 2.0, 1.6, ("stone",), ("wood",), ("small", "large", "small"))
    tower(s, 35.5, 1.0, 3, 2.0, 1.6, ("stone",), ("wood",), ("helmet", "small", "medium"))
    s.block("wood", 32, top + 0.125, 8.6, 0.25)  # the bridge, resting on both keeps
    tnt(s, 32, top + 0.25)
    roof(s, 28.5, top + 0.25, 2.6, "wood")
    roof(s, 35.5, top + 0.25, 2.6, "wood")
    cage(s, 32, 1.0, 1.2, "wood", "small")
    return level("6-4", "Twin Keeps",
                 "Two keeps joined by a bridge: the bridge carries the TNT. A shot that breaks the bridge drops the "
                 "crate between them; a shot at a keep's top tips it onto the other.",
                 ["The bridge is the weak point."],
                 ["red", "red", "black"], s, (15.0, 30))


def l6_3():
    s = Scene()
    hill(s, 24, 44, 3.5, 0.6)
    castle(s, 34, 3.5, 3, "wood", "wood", ("large", "medium", "helmet"), "ice")
    cage(s, 22.5, 0, 1.2, "ice", "small")
    cage(s, 45.5, 0, 1.2, "ice", None)
    return level("6-9", "Hill Fort",
                 "A fort on a hill in a headwind: the fort stands above the pouch and the wind of {wind} m/s "
                 "pushes the bird back. Range, height and drag at once.",
                 ["Clear the fort's wall with a low arc: the headwind takes most from high, slow shots."],
                 ["red", "yellow", "red", "black"], s, (47.5, 27),
                 environment={"air_density": EARTH_AIR, "wind": [-4, 0]},
                 claims=[("/hints/0", "best_angle:red < calm_best_angle:red")])


def l6_4():
    s = Scene()
    top = double_frame(s, 24, 0, 2.2, 1.6, "wood", "wood", ("small", "small"))
    tnt(s, 23.0, top)
    tnt(s, 25.0, top)
    top = double_frame(s, 31, 0, 2.2, 1.6, "wood", "wood", ("large", "medium"))
    tnt(s, 30.0, top)
    tnt(s, 32.0, top)
    top = tower(s, 37, 0, 3, 2.0, 1.6, ("wood",), ("wood",), ("helmet", "small", "small"))
    roof(s, 37, top, 2.6, "wood")
    ball(s, 20, 0, 0.8, "stone")
    return level("6-2", "Powder Kegs",
                 "Chains of explosions: a TNT crate that breaks pushes and damages everything near it, and "
                 "breaks the next crate, which explodes in turn.",
                 ["One crate sets off the next."],
                 ["red", "red"], s, (22.0, 22.0))


def l6_5():
    s = Scene()
    hill(s, 20, 46, 1.5, 0.85)
    castle(s, 33, 1.5, 4, "stone", "wood", ("helmet", "small", "large", "medium"), "stone")
    for x in (25.5, 40.5):
        top = pyramid(s, x, 1.5, 4, 0.6, "wood")
        s.pig("small", x, top)
    cage(s, 27.9, 1.5, 1.0, "wood", None)
    cage(s, 38.1, 1.5, 1.0, "wood", None)
    tnt(s, 33.55, 1.5 + 2.25, 0.5)
    return level("6-5", "Citadel",
                 "A citadel of stone keeps and wooden walls. Stone takes {strength:stone} N s, more than a red bird's "
                 "hit can push ({p_rebound:red} N s); the black bird's blast breaks it, and a keep that topples "
                 "crushes what is under it: look for the weak floor.",
                 ["The TNT sits in the keep's first floor."],
                 ["black", "red", "red", "yellow", "black"], s, (40.0, 21.21),
                 claims=[("/concept", "p_rebound:red < strength:stone")])


def l6_6():
    s = Scene()
    island(s, 24, 6.0, 5.0)
    island(s, 33, 9.0, 5.0)
    island(s, 41, 5.0, 5.0)
    for x, y, pig in ((24, 6.0, "medium"), (33, 9.0, "helmet"), (41, 5.0, "large")):
        top = frame(s, x, y, 2.0, 1.6, "wood", "wood", pig)
        roof(s, x, top, 2.6, "wood")
    pyramid(s, 28.5, 0, 4, 0.7, "ice")
    s.pig("small", 28.5, 2.8)
    cage(s, 37, 0, 1.2, "ice", "small")
    return level("6-10", "Island Fortress",
                 "Islands in a gusty sky: from {gust_t:1} s the wind is {gust_wx:1} m/s. The far island needs "
                 "the longest flight and the gust bends it most.",
                 ["Take the low islands first."],
                 ["red", "yellow", "blue", "red", "red"], s, (30.0, 30),
                 environment={"air_density": EARTH_AIR, "gusts": [{"t": 1.5, "wx": 5, "wy": 0}]})


def l6_7():
    s = Scene()
    castle(s, 30, 0, 3, "ice", "wood", ("large", "medium", "small"), "ice")
    double_frame(s, 38.5, 0, 2.0, 1.6, "ice", "ice", ("helmet", "small"))
    ball(s, 38.5, 1.85, 0.6, "ice")
    return level("6-1", "Frozen Fortress",
                 "A fortress of ice: light ({density:ice} kg/m^3) and brittle ({strength:ice} N s). The blue bird "
                 "splits into a flock in flight (click): its hits spread along the walls instead of striking one spot.",
                 ["Split the blue bird at the walls."],
                 ["blue", "red", "blue", "red", "red"], s, (2.5, 32.32))


def l6_8():
    s = Scene()
    plateau(s, -4, 4, 9.0)
    castle(s, 24, 0, 3, "wood", "wood", ("medium", "large", "small"), "wood")
    pyramid(s, 16, 0, 3, 0.7, "stone")
    cage(s, 31, 0, 1.2, "wood", "helmet")
    return level("6-3", "Cliff Castle",
                 "From a cliff {launch_height} m up a bird flies farther and can shoot down at the castle: the best "
                 "angle for range is below 45 degrees here ({vacuum_best_angle:red} degrees).",
                 ["Shots below the horizon reach the castle's walls."],
                 ["red", "red", "black", "red", "red"], s, (7.5, 18), slingshot={"x": 0, "y": 10.5})


def l6_9():
    s = Scene()
    hill(s, 30, 50, 1.5, 0.7)
    castle(s, 40, 1.5, 4, "wood", "wood", ("small", "large", "medium", "helmet"), "stone")
    tower(s, 34.2, 1.5, 1, 1.6, 1.6, ("stone",), ("wood",), ("small",))
    tower(s, 45.8, 1.5, 1, 1.6, 1.6, ("stone",), ("wood",), ("small",))
    cage(s, 51.5, 0, 0.9, "wood", None)
    return level("6-6", "Moon Citadel",
                 "A citadel on the Moon (g = {g} m/s^2): the bird flies {earth_g / g|1} times as far as on Earth at "
                 "the same speed, and the keep falls slowly.",
                 ["A light pull is enough."],
                 ["red", "red", "black", "red", "red"], s, (12.5, 14.0), slingshot=MOON_SLINGSHOT,
                 environment={"gravity": 1.62}, theme="moon")


def l6_10():
    s = Scene()
    hill(s, 21, 53, 1.5, 0.85)
    fortress(s, 30, 1.5, "stone", "wood", ("helmet", None, "large", "medium"), ("small", "small"))
    fortress(s, 44, 1.5, "stone", "wood", (None, "helmet", "medium", "large"), ("small", "small"))
    cage(s, 37, 1.5, 1.0, "wood", "small")
    tnt(s, 37, 2.5)
    tnt(s, 46.8, 2.3)  # on the right castle's far cage: its stone tower beyond has no other weak point
    gate(s, 15, 0, 2.4, 3, 0.6, "stone", "wood", "helmet")
    top = pyramid(s, 57, 0, 4, 0.8, "wood")
    s.pig("small", 57, top)
    return level("6-8", "The Last Fortress",
                 "Two stone castles with helmeted pigs: every idea of the campaign at once. Stone breaks in a blast, "
                 "seldom to a hit, and it topples; heavy birds carry momentum; TNT between the castles reaches both.",
                 ["The TNT between the castles is within reach of both.",
                  "The crate beside the right castle's far tower reaches the pig inside it."],
                 ["black", "red", "black", "red", "red"], s, (35.0, 21.21))


# The builder used by tools/make-levels --------------------------------------------------------------------------------

LEVELS = [l1_6, l1_7, l1_8, l2_6, l2_7, l2_8, l3_6, l3_7, l3_8, l4_6, l4_7, l4_8, l5_6, l5_7, l5_8,
          l6_1, l6_2, l6_3, l6_4, l6_5, l6_6, l6_7, l6_8, l6_9, l6_10]
