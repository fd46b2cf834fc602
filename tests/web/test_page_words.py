"""Words and letters a student reads, pinned by what the API serves (issue 40, item 7)."""

from __future__ import annotations

import pytest

SCENES_WITH_A_REDUCTION = ["tabletop-spring", "spherical-pendulum", "rotating-parabola", "helix-bead"]


def steps(client, scene: str) -> dict[str, dict]:
    return {s["key"]: s for s in client.get(f"/api/scenes/{scene}/derivation").json()["steps"]}


@pytest.mark.parametrize("scene", SCENES_WITH_A_REDUCTION)
def test_the_energy_integral_uses_the_pages_own_letter(client, scene):
    shown = steps(client, scene)
    energy, time = shown["energy-integral"]["latex"], shown["time-integral"]["latex"]
    assert "E_r" not in energy + time and "E_{r}" not in energy + time
    # the rotating parabola's conserved quantity is h (h ≠ E in the rotating set-up); the others', E
    letter = "h" if scene == "rotating-parabola" else "E"
    assert energy.startswith(f"{letter} = ") and f"\\left({letter} - U_\\text{{eff}}" in time


def test_the_tabletop_energy_integral_is_kinetic_then_u_eff_as_printed_a_step_before(client):
    shown = steps(client, "tabletop-spring")
    u_eff = (
        shown["effective-potential"]["latex"][0] if isinstance(shown["effective-potential"]["latex"], list) else None
    )
    energy = shown["energy-integral"]["latex"]
    assert energy == r"E = \frac{1}{2} m \dot{r}^{2} + \frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}"
    assert u_eff is None or u_eff.endswith(r"\frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}")


def test_the_helix_winding_is_described_in_its_unit(client):
    alpha = client.get("/api/scenes/helix-bead/derivation").json()["parameters"]["alpha"]
    assert alpha["unit"] == "rad/m" and "radians" in alpha["description"] and "turns of" not in alpha["description"]
    assert "radians of turn per metre" in client.get("/scenes/helix-bead").text
