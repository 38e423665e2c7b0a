"""The papers' figures that a matrix reproduces, with their captions.

Each entry maps a (scenario, gait) of the suite to a figure of one of the two
papers, the figure's caption as printed (or the sentence of the text that
describes it), and which images the report draws for it: a side-view film
strip (``side``), the leg-state diagram of the last second (``gait``), or the
top view (``top``).  ``gait = None`` matches any gait.
"""
from __future__ import annotations

from dataclasses import dataclass

FANG = "Fang, Jiang & Terzopoulos, SCA 2013"
MILLER = "Miller, SIGGRAPH 1988"


@dataclass(frozen=True)
class PaperFigure:
    scenario: str
    gait: str | None
    figure: str
    paper: str
    caption: str
    images: tuple[str, ...]  # "side", "gait", "top"


PAPER_FIGURES: tuple[PaperFigure, ...] = (
    PaperFigure("fig4-drop", None, "Figure 4", FANG,
                "A dynamic structure with alternating, coupled rigid and deformable segments dropping onto a "
                "slippery ground plane.", ("side",)),
    PaperFigure("drop-adjust", None, "Figure 10 (B)-(D)", FANG,
                "A centipede dropped to the ground. The right panel shows the states of each leg during the last "
                "second. (Sec. 4.2: dropped to the ground, the legs start to enter the STANCE and ADJUST states; "
                "when the creature starts walking, each leg converges to SF1 -> SF2 -> STANCE with short ADJUST "
                "and SB1.)", ("side", "gait")),
    PaperFigure("hang", None, "Figure 10 (A)", FANG,
                "When hanging in gravity, the body model will naturally elongate (Sec. 3). When the simulated "
                "myriapod is suspended off the ground, the legs will periodically go from the SF1 to the SB2 "
                "states without entering the STANCE and ADJUST states (Sec. 4.2).", ("side", "gait")),
    PaperFigure("walk", None, "Figure 10 (D) and Sec. 6", FANG,
                "When the creature starts walking, its leg motions quickly converge to a wave pattern in which "
                "each leg undergoes the state cycle SF1 -> SF2 -> STANCE with short appearances of the ADJUST and "
                "SB1 states (Sec. 4.2).", ("gait", "top")),
    PaperFigure("control", None, "Sec. 4.3 (CONTROL)", FANG,
                "The user can take control of the creature's movement (CONTROL mode): the head follows commanded "
                "speed and turn rate.", ("top", "gait")),
    PaperFigure("fig1-mesh", None, "Figure 1", FANG,
                "A simulated centipede walking autonomously over a crystal skull.", ("side", "top")),
    PaperFigure("fig12-water-foraging", None, "Figure 12", FANG,
                "A centipede walking in shallow water, attracted by food (green spheres) and avoiding obstacles.",
                ("top", "gait")),
    PaperFigure("fig13-cylinders", None, "Figure 13", FANG,
                "Walking over an irregular surface paved with random cylinders.", ("top", "gait")),
    PaperFigure("foraging", None, "Sec. 6.2 (foraging)", FANG,
                "In our real-time simulator, food and obstacles can be generated randomly in the scene to elicit "
                "the emergent behavior of an autonomous myriapod creature exploring its environment.", ("top",)),
    PaperFigure("terrain", None, "Sec. 6.2 (terrain)", FANG,
                "Irregular terrain: a height field from a mixture of Gaussians; the legs find footholds on the "
                "uneven ground.", ("side", "top")),
    PaperFigure("cliff", "rectilinear", "Images 1a-1d", MILLER,
                "A worm in free-fall colliding with the constraint, in this case a book ... wriggling towards a "
                "vertical edge. The front begins to bend downwards under the weight ... the worm sliding off the "
                "edge.", ("side", "top")),
    PaperFigure("flat", "lateral-undulation", "Images 2a-2d", MILLER,
                "The snake ... undulations deforming the snake ... the coils fully formed ... the segments are now "
                "all very nearly following each other along the same path.", ("top",)),
    PaperFigure("flat", "sidewinding", "Images 3a-3d", MILLER,
                "The sidewinder as the coils are forming. The back arches and the contact with the ground is "
                "localised ... progression begins to take effect.", ("top", "side")),
    PaperFigure("slope", "arching", "Images 4a-4b", MILLER,
                "The caterpillar at rest ... arching its back. Eliminating all tangential movement for segments "
                "in contact gives the caterpillar the ability to scale steep gradients.", ("side",)),
)

# The myriapod paper's throughput headline (Sec. 6): 18 segments, 3x3x3 mesh, 6-core i7-3930K with OpenMP.
PAPER_STEPS_PER_S = 1.7e4
PAPER_THROUGHPUT_NOTE = ("An Intel Core i7-3930k (6 core, 3.2 GHz) machine can update an 18 segment centipede model "
                         "with 3 x 3 x 3 deformable mesh resolution at a rate of 1.7 x 10^4 time-steps per second; "
                         "a time step of 1/3000 s gives about 6x real-time speed (Sec. 6).")


def figure_for(scenario: str, gait: str) -> PaperFigure | None:
    """The paper figure a case reproduces, or None."""
    for f in PAPER_FIGURES:
        if f.scenario == scenario and (f.gait is None or f.gait == gait):
            return f
    return None
