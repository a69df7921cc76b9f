"""The rig's geometry and inertia, and the rigid (clearance-free) kinematics.

Written from the thesis (ch. 2, Table 6.1) and docs/acquire.md's sign
conventions, not from fourbar's C++. SI units inside (m, kg, s, rad).

Notation: O2 = (0, 0) the crank pivot, O4 = (l1, 0) the rocker pivot,
A = l2·u2 the crank pin, u_i = (cos θi, sin θi), n_i = (−sin θi, cos θi).
The coupler runs from A to its pin centre B3, the rocker from O4 to its
bushing centre C4; without clearance B3 = C4.
"""
from dataclasses import dataclass
import math
import tomllib


@dataclass(frozen=True)
class Link:
    length_m: float
    mass_centre_m: float
    mass_kg: float
    inertia_kg_m2: float  # about the mass centre

    @property
    def inertia_about_joint_kg_m2(self) -> float:
        """Inertia about the link's first joint (parallel axes)."""
        return self.inertia_kg_m2 + self.mass_kg * self.mass_centre_m ** 2


@dataclass(frozen=True)
class Rig:
    name: str
    gravity_m_s2: float
    ground_m: float
    crank: Link
    coupler: Link
    rocker: Link
    clearance_m: float
    path: str


def load_rig(path: str) -> Rig:
    """Reads a fourbar rig file (data/rigs/*.toml: mm, kg, kg·mm²)."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    if doc.get("assembly", "open") != "open":
        raise SystemExit(f"{path}: only assembly = \"open\" is modelled here")

    def link(key: str) -> Link:
        t = doc[key]
        return Link(t["length_mm"] * 1e-3, t["mass_centre_mm"] * 1e-3,
                    t["mass_kg"], t["inertia_kg_mm2"] * 1e-6)

    return Rig(name=doc.get("name", path),
               gravity_m_s2=doc.get("gravity_m_s2", 9.80665),
               ground_m=doc["ground"]["length_mm"] * 1e-3,
               crank=link("crank"), coupler=link("coupler"), rocker=link("rocker"),
               clearance_m=doc.get("clearance", {}).get("radial_mm", 0.0) * 1e-3,
               path=path)


def nominal_angles(rig: Rig, theta2: float) -> tuple[float, float]:
    """θ3, θ4 of the rigid linkage: B is where the circles about A (radius l3)
    and O4 (radius l4) meet, on the left of the line A→O4 (the "open"
    assembly: B above the ground line at θ2 = 0)."""
    l1, l2, l3, l4 = rig.ground_m, rig.crank.length_m, rig.coupler.length_m, rig.rocker.length_m
    ax, ay = l2 * math.cos(theta2), l2 * math.sin(theta2)
    dx, dy = l1 - ax, -ay                      # A → O4
    d = math.hypot(dx, dy)
    along = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d)  # from A towards O4
    h = math.sqrt(max(l3 * l3 - along * along, 0.0))
    ex, ey = dx / d, dy / d
    bx = ax + along * ex - h * ey                # left of A→O4: rotate +90°
    by = ay + along * ey + h * ex
    return math.atan2(by - ay, bx - ax), math.atan2(by, bx - l1)


def nominal_rates(rig: Rig, theta2: float, omega2: float, alpha2: float):
    """(θ3, θ4, ω3, ω4, α3, α4) of the rigid linkage, from differentiating the
    loop l2·u2 + l3·u3 − l4·u4 = (l1, 0) twice (solved as 2×2 systems)."""
    l2, l3, l4 = rig.crank.length_m, rig.coupler.length_m, rig.rocker.length_m
    t3, t4 = nominal_angles(rig, theta2)
    # velocity loop: l2 ω2 n2 + l3 ω3 n3 − l4 ω4 n4 = 0
    s2, c2, s3, c3, s4, c4 = (math.sin(theta2), math.cos(theta2), math.sin(t3),
                              math.cos(t3), math.sin(t4), math.cos(t4))
    det = (-l3 * s3) * (-l4 * c4) - (l4 * s4) * (l3 * c3)
    # [−l3 s3, l4 s4; l3 c3, −l4 c4] [ω3; ω4] = [l2 ω2 s2; −l2 ω2 c2]
    rx, ry = l2 * omega2 * s2, -l2 * omega2 * c2
    w3 = (rx * (-l4 * c4) - (l4 * s4) * ry) / det
    w4 = ((-l3 * s3) * ry - (l3 * c3) * rx) / det
    # acceleration loop: Σ l (α n − ω² u) with signs as above
    rx = l2 * (alpha2 * s2 + omega2 ** 2 * c2) + l3 * w3 ** 2 * c3 - l4 * w4 ** 2 * c4
    ry = -l2 * (alpha2 * c2 - omega2 ** 2 * s2) + l3 * w3 ** 2 * s3 - l4 * w4 ** 2 * s4
    a3 = (rx * (-l4 * c4) - (l4 * s4) * ry) / det
    a4 = ((-l3 * s3) * ry - (l3 * c3) * rx) / det
    return t3, t4, w3, w4, a3, a4
