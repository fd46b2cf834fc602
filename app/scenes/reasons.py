"""Why each step of a chapter scene's derivation reads as it does, in that scene (plain data).

Each table belongs to one scene, which holds it as its ``reasons`` (``Scene.reasons``).

A scene's page explains every step with the sentence here instead of the engine's generic
one (which stays for user systems).  Keys are the steps' keys (app/engine/document/report.py), never
their titles; a key without a colon (``normal-modes``) also matches every step of that kind
(``normal-modes:1``, ``normal-modes:2``) that has no reason of its own.
"""

from __future__ import annotations

from collections.abc import Mapping

# Steps every scene shares whose reason depends only on the scene's conservative, autonomous L.
_LEGENDRE = (
    "Solving the momenta, which are linear in the velocities, for the velocities is the first step of writing h "
    "as a function of q and p."
)


def _hamiltonian(what: str) -> dict[str, str]:
    return {
        "legendre": _LEGENDRE,
        "hamiltonian-pq": f"H is h with the velocities replaced by the momenta: {what}.",
        "hamilton-equations": "q̇ = ∂H/∂p and ṗ = −∂H/∂q: the same motion as the Euler–Lagrange equations, "
        "as twice as many first-order equations.",
    }


def _h_is_e(still: str) -> str:
    """The "Is h equal to E?" step of a scene whose positions do not depend on t (``still`` says why).

    Two separate conditions: positions free of t make h = E; h is conserved because L has no explicit t and
    no non-conservative force does work.
    """
    return (
        f"{still}, so h = E. Separately, L has no explicit t and no non-conservative force does work, "
        "so h is conserved, and E with it."
    )


SIMPLE_PENDULUM: dict[str, str] = {
    "action": "Of all the ways the bob could swing from one angle to another in the same time, the real swing makes ∫ (T − U) dt stationary; once the time passes the first kinetic focus (about half a small swing) it is a saddle, not the least.",
    "positions": "The bob is R from the pivot at angle θ from the downward vertical; the origin is at the lowest point.",
    "velocities": "Only θ changes, so the bob moves along the circle with speed R θ̇.",
    "squared-speeds": "On a circle of radius R the squared speed is R² θ̇², whatever the angle.",
    "kinetic": "A single bob moving at R θ̇: T = ½ m R² θ̇².",
    "potential": "The bob is R (1 − cos θ) above its lowest point, so U = m g R (1 − cos θ).",
    "lagrangian": "T − U with one coordinate: the smallest system the recipe applies to.",
    "derivatives:theta": "∂L/∂θ = −m g R sin θ is gravity's torque about the pivot; ∂L/∂θ̇ = m R² θ̇ is the angular momentum.",
    "euler-lagrange": "Angular momentum changes at the rate of the torque; divided by m R² the mass drops out.",
    "mass-matrix": "One coordinate: ℳ is the moment of inertia m R² and f is the torque −m g R sin θ.",
    "accelerations": "θ̈ = −(g/R) sin θ: the mass does not matter, only g/R.",
    "momenta": "p_θ = m R² θ̇ is the bob's angular momentum about the pivot.",
    "time-dependence": "Nothing in the set-up moves or changes with time, so L has no t in it.",
    "hamiltonian": "T is quadratic in θ̇, so h is T + U.",
    "energy": "The bob's kinetic plus gravitational energy.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("p_θ²/(2 m R²) + m g R (1 − cos θ)"),
    "effective-potential": "With a single coordinate there is nothing to fold in: U_eff is U itself.",
    "energy-integral": "Energy conservation gives θ̇ as a function of θ, one integration from the motion.",
    "time-integral": "Taken between the turning points, this integral is half the period of a wide swing (there and back is a whole one): an elliptic integral.",
    "reduced-equilibria": "The bottom (θ = 0) is stable with ω² = g/R; the top (θ = π) is unstable.",
    "equilibria": "sin θ = 0 at the bottom and at the top of the circle, and nowhere else.",
    "normal-modes": "Linearising sin θ about each equilibrium gives ω² = g/R at the bottom and −g/R at the top.",
    "constraints": "The string keeps the bob on the circle of radius R about the pivot at height R, in the plane of the swing (y = 0).",
    "multiplier-lagrangian": "The bob is free in x and z once the string is replaced by λ: gravity pulls down, the string pulls with the force λ ∇𝒞, and ∇𝒞 = −2(x, z − R) points from the bob to the pivot; with this sign of 𝒞, λ > 0 while the string is taut.",
    "multiplier-equation": "Differentiating x² + (z − R)² = R² twice brings in ẋ² + ż², the square of the speed: the tension will hold a centripetal part.",
    "multiplier": "λ₁ is the tension divided by 2R, since |∇𝒞₁| = 2R on the circle.",
    "constraint-forces": "The tension must supply the centripetal force m R θ̇² plus gravity's pull along the string.",
}


DAMPED_PENDULUM: dict[str, str] = {
    "action": "With friction the principle needs the friction's virtual work beside δS: the real swing makes δS + ∫ Q δθ dt vanish, not S alone stationary.",
    "positions": "The bob is R from the pivot at angle θ from the downward vertical, as in the simple pendulum.",
    "velocities": "Only θ changes, so the bob moves along the circle with speed R θ̇.",
    "squared-speeds": "On the circle the squared speed is R² θ̇².",
    "kinetic": "T = ½ m R² θ̇², unchanged by the drag.",
    "potential": "Gravity alone has a potential, m g R (1 − cos θ); the drag has none.",
    "lagrangian": "The same L as without drag: the drag cannot be written into it.",
    "derivatives:theta": "The same derivatives as the simple pendulum: torque −m g R sin θ and angular momentum m R² θ̇.",
    "generalized-forces": "The drag's torque about the pivot is the generalized force on θ: Q_θ = −b θ̇, opposing the swing.",
    "euler-lagrange": "The drag adds (b/(m R²)) θ̇ to the pendulum's equation: a damping term.",
    "mass-matrix": "ℳ = m R² as before; f now includes the drag −b θ̇.",
    "accelerations": "θ̈ = −(g/R) sin θ − (b/(m R²)) θ̇: gravity restores, drag slows.",
    "momenta": "p_θ = m R² θ̇, unchanged by the drag.",
    "time-dependence": "L has no t, yet h is not conserved because the drag does work.",
    "hamiltonian": "h = T + U, as for the undamped pendulum.",
    "energy": "The bob's kinetic plus gravitational energy, which the drag drains.",
    "h-vs-e": "The positions do not depend on t, so h = E. That says nothing about conservation: the drag does "
    "work, so h (and E with it) decays.",
    "power": "h, which equals E here, falls at the rate b θ̇² whenever the bob moves.",
    **_hamiltonian("p_θ²/(2 m R²) + m g R (1 − cos θ), with the drag added to ṗ"),
    "equilibria": "The drag vanishes at rest, so the equilibria are the simple pendulum's: bottom and top.",
    "normal-modes": "About the bottom the motion is a damped oscillation; about the top it runs away.",
    "constraints": "The string keeps the bob on the circle of radius R about the pivot, in the plane of the swing.",
    "multiplier-lagrangian": "Newton's law for the free bob with the string's pull λ ∇𝒞; the drag joins it along the motion, tangent to the circle.",
    "multiplier-equation": "The drag is tangent to the circle, so it has no part along ∇𝒞 and drops out of the equation for λ.",
    "multiplier": "The same λ as the undamped pendulum's at the same θ and θ̇: damping changes the motion, not the tension's formula.",
    "constraint-forces": "The tension holds the bob on its circle: centripetal force plus gravity along the string.",
}


HELIX_BEAD: dict[str, str] = {
    "action": "Of all the ways the bead could slide between two heights in the same time, the real one makes ∫ L dt stationary; in uniform gravity there is no kinetic focus, so it is the least for any time.",
    "positions": "The bead's height z fixes its turn φ = α z, so it sits at (R cos αz, R sin αz, z).",
    "velocities": "Rising at the rate ż, the bead turns at the rate α ż, so it moves at R α ż around the axis.",
    "squared-speeds": "Vertical and circular motions are perpendicular: v² = (1 + α² R²) ż².",
    "kinetic": "The winding gives the bead more inertia along z, not more weight: its effective mass for motion in z is m(1 + α² R²).",
    "potential": "Only the height matters for gravity: U = m g z.",
    "lagrangian": "A free fall along z with an enlarged inertia.",
    "derivatives:z": "∂L/∂z = −m g is the weight; ∂L/∂ż = m (1 + α² R²) ż is the momentum conjugate to z.",
    "euler-lagrange": "Constant acceleration: the full weight m g acts on an inertia enlarged to m (1 + α² R²), so the bead falls more slowly than a free body.",
    "mass-matrix": "ℳ = m (1 + α² R²), the inertia z moves with; f = −m g, the weight.",
    "accelerations": "z̈ = −g/(1 + α² R²): a tighter helix falls more slowly.",
    "momenta": "p_z = m (1 + α² R²) ż is the momentum conjugate to z, not the bead's momentum along the wire: the bead moves along the wire at the speed √(1 + α² R²) ż, so its momentum there is m √(1 + α² R²) ż, and p_z is that times dℓ/dz = √(1 + α² R²), the length of wire per unit of height.",
    "time-dependence": "The wire is fixed, so L has no t.",
    "hamiltonian": "T is quadratic in ż, so h is T + U.",
    "energy": "Kinetic energy of the winding motion plus m g z.",
    "h-vs-e": _h_is_e("The wire does not move, so the positions do not depend on t"),
    **_hamiltonian("p_z²/(2 m (1 + α² R²)) + m g z"),
    "effective-potential": "One coordinate and no cyclic one: U_eff is m g z, with the effective mass of the winding.",
    "energy-integral": "Energy conservation gives ż from z: a uniformly accelerated motion.",
    "time-integral": "The integral gives the parabola of a uniform acceleration g/(1 + α² R²).",
    "equilibria": "Gravity along z never balances on a frictionless wire, so there is none.",
    "constraints": "The wire is two surfaces at once: the cylinder of radius R and the helicoid that winds it.",
    "multiplier-lagrangian": "Two multipliers, one for each surface: λ₁ pushes toward the axis, λ₂ across the helix.",
    "multiplier-equation": "The cylinder's normal points toward the axis; the helicoid's lies in the cylinder's surface, across the helix.",
    "multiplier": "On the helix ξ = R cos αz and η = R sin αz: λ₁ carries the circular motion's ż², λ₂ the weight the slope does not take.",
    "constraint-forces": "The wire pushes toward the axis for the circular motion and across the helix to turn the bead.",
}


INCLINE_BLOCK: dict[str, str] = {
    "action": "Of all the ways the block could slide between two points of the incline in the same time, the real one makes ∫ L dt stationary; with a constant force it is the least for any time.",
    "positions": "The block is X along the slope, so X cos α across and X sin α up.",
    "velocities": "The block moves along the slope only, at speed Ẋ.",
    "squared-speeds": "cos² α + sin² α = 1: the squared speed is Ẋ².",
    "kinetic": "T = ½ m Ẋ², as on a flat track.",
    "potential": "The block's height is X sin α, so U = m g X sin α.",
    "lagrangian": "A particle on a line under the constant force m g sin α down the slope.",
    "derivatives:X": "∂L/∂X = −m g sin α is gravity's component down the slope; ∂L/∂Ẋ = m Ẋ is the momentum.",
    "euler-lagrange": "Only the slope's share of gravity, g sin α, accelerates the block.",
    "mass-matrix": "ℳ = m; the force f = −m g sin α along the slope is constant.",
    "accelerations": "Ẍ = −g sin α: constant, independent of the mass.",
    "momenta": "p_X = m Ẋ, the momentum along the slope.",
    "time-dependence": "The incline is fixed, so L has no t.",
    "hamiltonian": "T is quadratic in Ẋ, so h is T + U.",
    "energy": "½ m Ẋ² plus m g X sin α.",
    "h-vs-e": _h_is_e("The incline does not move, so the positions do not depend on t"),
    **_hamiltonian("p_X²/(2m) + m g X sin α"),
    "effective-potential": "With one coordinate, U_eff is the slope's potential m g X sin α.",
    "energy-integral": "Energy conservation gives Ẋ from X for the uniformly accelerated slide.",
    "time-integral": "The integral recovers X(t), a parabola in t.",
    "equilibria": "On a frictionless slope nothing holds the block, so there is none.",
    "constraints": "The block stays on the plane through the origin tilted at α.",
    "multiplier-lagrangian": "Newton's law for the free block with the plane's push λ along the normal (−sin α, 0, cos α).",
    "multiplier-equation": "The plane is flat: 𝒞̈ has no velocity terms, and the equation holds only gravity's part along the normal.",
    "multiplier": "λ is the normal force itself, as the normal (−sin α, 0, cos α) has length 1.",
    "constraint-forces": "The normal force balances gravity's component into the plane: m g cos α.",
}


TABLETOP_SPRING: dict[str, str] = {
    "action": "Of all the paths across the table between two positions in the same time, the real one makes ∫ L dt stationary; the spring pulls like an oscillator, so after half its period π √(m/k) the true path is a saddle: a variation of r and θ together lowers S, while varying r or θ alone reaches its focus later or never.",
    "positions": "Polar coordinates about the spring's anchor on the table: (r cos θ, r sin θ, 0).",
    "velocities": "ṙ along the radius and r θ̇ around it.",
    "squared-speeds": "The radial and angular motions are perpendicular: v² = ṙ² + r² θ̇².",
    "kinetic": "Radial plus angular kinetic energy, ½ m ṙ² + ½ m r² θ̇².",
    "potential": "A spring of zero rest length stores ½ k r².",
    "lagrangian": "θ does not appear in L: the set-up is the same in every direction.",
    "derivatives:r": "∂L/∂r holds the centrifugal term m r θ̇² and the spring's pull −k r.",
    "derivatives:theta": "∂L/∂θ = 0, so p_θ = m r² θ̇ is constant: the angular momentum.",
    "euler-lagrange": "In the radial equation m r̈ is the spring's pull −k r plus the centrifugal term m r θ̇²; the two cancel only on the circular orbit. The angular one says m r² θ̇ is constant.",
    "mass-matrix": "ℳ is diagonal: m for r and the moment of inertia m r² for θ.",
    "accelerations": "r̈ = r θ̇² − (k/m) r and θ̈ = −2 ṙ θ̇/r: the second is the conservation of angular momentum.",
    "momenta": "p_r = m ṙ and the angular momentum p_θ = m r² θ̇.",
    "cyclic": "Turning the whole motion about the anchor changes nothing, so p_θ is conserved.",
    "time-dependence": "The spring and the table are fixed, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "Kinetic energy plus the spring's ½ k r².",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("(p_r² + p_θ²/r²)/(2m) + ½ k r²"),
    "cyclic-velocities": "θ̇ = p_θ/(m r²) with p_θ fixed by the initial push.",
    "effective-potential": "The spring's ½ k r² plus the centrifugal barrier p_θ²/(2 m r²).",
    "energy-integral": "The radial motion alone, at fixed p_θ, conserves this energy.",
    "time-integral": "Integrating between the turning points of U_eff gives half the radial period: out and back in again is a whole one.",
    "reduced-equilibria": "The circular orbit sits where the spring balances the centrifugal force.",
    "equilibria": "No position of rest other than at the anchor: the spring pulls everything else in.",
    "steady-motion": "About the circular orbit r oscillates at ω² = 4k/m, twice the spring's own frequency.",
}


SPHERICAL_PENDULUM: dict[str, str] = {
    "action": "Of all the ways over the sphere between two points in the same time, the real one makes ∫ L dt stationary; gravity pulls back toward the bottom, so long enough stretches of motion are saddles of S; the first kinetic focus, of θ and φ varied together, comes before that of θ or φ varied alone.",
    "positions": "Spherical coordinates about the pivot, with θ from the upward vertical.",
    "velocities": "R θ̇ along a meridian and R sin θ φ̇ along a parallel.",
    "squared-speeds": "The two directions are perpendicular: v² = R² θ̇² + R² sin² θ φ̇².",
    "kinetic": "The motion along the meridian plus the turning about the vertical axis.",
    "potential": "The ball's height above the pivot is R cos θ, so U = m g R cos θ.",
    "lagrangian": "φ does not appear in L: the set-up is symmetric about the vertical axis.",
    "derivatives:theta": "∂L/∂θ holds the centrifugal term of the turning and gravity's torque.",
    "derivatives:phi": "∂L/∂φ = 0: the angular momentum about the vertical axis is conserved.",
    "euler-lagrange": "θ feels gravity and the centrifugal effect of φ̇; φ keeps m R² sin² θ φ̇ constant.",
    "mass-matrix": "ℳ is diagonal: m R² for θ and m R² sin² θ for φ.",
    "accelerations": "The ball turns faster the nearer it comes to the vertical axis (sin θ smaller), above or below the pivot.",
    "momenta": "p_φ = m R² sin² θ φ̇ is the angular momentum about the vertical axis.",
    "cyclic": "Rotating about the vertical axis changes nothing, so p_φ is conserved.",
    "time-dependence": "The pivot is fixed, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "Kinetic energy plus m g R cos θ.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("p_θ²/(2 m R²) + p_φ²/(2 m R² sin² θ) + m g R cos θ"),
    "cyclic-velocities": "φ̇ = p_φ/(m R² sin² θ) with p_φ fixed by the initial push.",
    "effective-potential": "Gravity plus the barrier p_φ²/(2 m R² sin² θ) that keeps the ball off the axis.",
    "energy-integral": "At fixed p_φ, θ moves in U_eff between two turning angles.",
    "time-integral": "The time between the turning angles is half the period of the nodding motion: down and up again is a whole one.",
    "reduced-equilibria": "The conical motion sits at the bottom of U_eff, below the horizontal; U_eff′(θ₀) = 0 fixes p_φ by θ₀, so ω² is written in θ₀ alone.",
    "equilibria": "At rest the ball can hang at the bottom or balance at the top.",
    "steady-motion": "About the conical motion θ nods with the frequency given by U_eff″ at its bottom.",
    "constraints": "The string keeps the ball on the sphere of radius R about the pivot.",
    "multiplier-lagrangian": "The ball is free in x, y and z once the string is replaced by λ; the string pulls with the force λ ∇𝒞, and ∇𝒞 = −2(x, y, z) points from the ball to the pivot; with this sign of 𝒞, λ > 0 while the string is taut.",
    "multiplier-equation": "Differentiating x² + y² + z² = R² twice brings in the squared speed ẋ² + ẏ² + ż².",
    "multiplier": "On the sphere the squared speed is R²(θ̇² + φ̇² sin²θ): both motions load the string.",
    "constraint-forces": "The tension supplies the centripetal force of the motion on the sphere plus gravity's pull.",
}


RAIL_TWO_BODY: dict[str, str] = {
    "action": "The two masses move so that ∫ L dt is stationary between two configurations; the spring gives their relative motion a kinetic focus half its period after the start, past which a variation that moves both masses lowers S (a saddle); varying x₁ or x₂ alone, the focus comes later.",
    "positions": "Both masses are on the rail, so each is given by its own x.",
    "velocities": "Each mass moves with its own ẋ along the rail.",
    "squared-speeds": "On a line the squared speed is ẋ² for each mass.",
    "kinetic": "The two masses' kinetic energies simply add.",
    "potential": "The spring is stretched by x₂ − x₁ − l₀ beyond its rest length.",
    "lagrangian": "The positions enter only through x₂ − x₁: moving both together changes nothing.",
    "derivatives:x1": "∂L/∂x₁ is the spring's push on mass 1; ∂L/∂ẋ₁ = m₁ ẋ₁ its momentum.",
    "derivatives:x2": "The spring pushes mass 2 the opposite way, with the same size.",
    "euler-lagrange": "Newton's law for each mass with equal and opposite spring forces.",
    "mass-matrix": "ℳ is diagonal, m₁ and m₂: the masses are coupled only through the spring.",
    "accelerations": "Each acceleration is the spring force over that mass.",
    "momenta": "p_x₁ = m₁ ẋ₁ and p_x₂ = m₂ ẋ₂ are the two masses' momenta; their sum p_x₁ + p_x₂ is conserved.",
    "time-dependence": "Rail and spring are fixed, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "Both kinetic energies plus the spring's.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("p_x₁²/(2m₁) + p_x₂²/(2m₂) + ½ k (x₂ − x₁ − l₀)²"),
    "equilibria": "At rest the spring is at its rest length, x₂ − x₁ = l₀, anywhere on the rail.",
    "normal-modes": "One mode is a free drift of both masses (ω = 0); the other is the spring's oscillation, ω² = k/μ.",
    "change-of-coordinates": "The centre of mass X and the separation x split the motion into two independent parts.",
    "inverse-map": "x₁ and x₂ are recovered from X and x with the mass fractions.",
    "new-lagrangian": "X appears only through Ẋ, and x carries the spring.",
    "new-inertia": "The total mass moves X; the reduced mass μ = m₁m₂/(m₁ + m₂) moves x.",
    "new-equations": "Ẍ = 0 and a simple harmonic x of frequency √(k/μ).",
    "conserved:p_X": "The total momentum (m₁ + m₂) Ẋ = m₁ ẋ₁ + m₂ ẋ₂ never changes.",
}


PULLEY: dict[str, str] = {
    "action": "The masses move so that ∫ L dt is stationary between two positions; with constant gravity and no spring there is no kinetic focus, and the true path is a minimum of the action for every duration.",
    "positions": "The end masses hang at heights y₁ and y₂, a distance d either side of the middle; the string fixes the middle mass at −(y₁ + y₂)/2 − c.",
    "velocities": "The middle mass moves at Ẏ = −(ẏ₁ + ẏ₂)/2, minus half the sum of the end masses' velocities.",
    "squared-speeds": "Each mass moves vertically only.",
    "kinetic": "The middle mass moves at −(ẏ₁ + ẏ₂)/2, so its ⅛ M (ẏ₁ + ẏ₂)² couples the two coordinates: multiplied out it holds ¼ M ẏ₁ ẏ₂.",
    "potential": "Gravity on all three masses; the middle one is lower when the ends are higher.",
    "lagrangian": "Two coordinates for three masses: the string removed one.",
    "derivatives:y1": "∂L/∂y₁ = M g/2 − m₁ g is the generalized force on y₁: half the middle weight, pulled through the string, less mass 1's own weight.",
    "derivatives:y2": "∂L/∂y₂ = M g/2 − m₂ g, the same for mass 2.",
    "euler-lagrange": "The two equations share the middle mass's inertia M/4.",
    "mass-matrix": "The mass matrix ℳ (M is the middle body's mass) is not diagonal: the middle mass responds to both ends.",
    "accelerations": "Constant accelerations: every force here is a constant weight. The middle mass follows from Y = −(y₁ + y₂)/2 − c: Ÿ = −(ÿ₁ + ÿ₂)/2 = [4m₁m₂ − M(m₁ + m₂)] g/[4m₁m₂ + M(m₁ + m₂)].",
    "momenta": "Each momentum includes the middle mass's share of the motion.",
    "time-dependence": "The fixed pulleys do not move, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "Kinetic plus gravitational energy of all three masses.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("the kinetic energy written with the inverse mass matrix, plus the weights"),
    "equilibria": "The generalized forces are constant: with m₁ = m₂ = M/2 they vanish and every position is an equilibrium; otherwise (at the default masses, too) there is none.",
    "constraints": "With ζ₁, ζ₂, ζ₃ the heights of m₁, m₂ and M (ζ₁ = y₁, ζ₂ = y₂, ζ₃ = Y, all in metres), the string's length fixes ζ₁ + ζ₂ + 2ζ₃ = −2c, the constant c placing M below the end masses.",
    "multiplier-lagrangian": "Three free masses, each pulled up by the string: λ on each end mass, 2λ on the movable pulley (∂𝒞/∂ζ₃ = 2).",
    "multiplier-equation": "The string's length is fixed, so the accelerations obey ζ̈₁ + ζ̈₂ + 2 ζ̈₃ = 0: each mass's inertia enters through 1/m.",
    "multiplier": "No velocities enter: the tension is constant while the masses move.",
    "constraint-forces": "Since ∂𝒞/∂ζ₁ = 1, λ itself is the tension: the string's upward pull on mass 1, the same along the whole string; on the movable pulley it pulls with twice that.",
}


MOVABLE_INCLINE: dict[str, str] = {
    "action": "Block and wedge move so that ∫ L dt is stationary between two configurations; every force is constant, so there is no kinetic focus and the true path is a minimum of the action for every duration.",
    "positions": "The wedge's corner is at X; the block is D down its slope, at x = X + D cos α across and height z = −D sin α.",
    "velocities": "The block's velocity adds the wedge's Ẋ to its own slide Ḋ along the slope.",
    "squared-speeds": "The slide and the wedge's motion are at angle α, hence the cross term 2 Ẋ Ḋ cos α.",
    "kinetic": "The cross term m Ẋ Ḋ cos α couples the block to the wedge.",
    "potential": "The block descends D sin α; the wedge's height does not change.",
    "lagrangian": "X appears only through Ẋ: the floor is the same everywhere.",
    "derivatives:X": "∂L/∂X = 0: the horizontal momentum of the pair is conserved.",
    "derivatives:D": "∂L/∂D = m g sin α is gravity along the slope.",
    "euler-lagrange": "The first says the total horizontal momentum is constant; the second is the slide.",
    "mass-matrix": "The mass matrix ℳ (M is the wedge's mass) is not diagonal: sliding the block pushes the wedge back.",
    "accelerations": "Both accelerations are constant, the wedge's opposite to the block's horizontal motion.",
    "momenta": "p_X = (M + m) Ẋ + m Ḋ cos α is the total horizontal momentum.",
    "cyclic": "The floor is uniform, so p_X is conserved.",
    "time-dependence": "Nothing is driven, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "Kinetic energy of both bodies plus the block's gravitational energy, −m g D sin α.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("the kinetic energy written with the inverse mass matrix, minus m g D sin α"),
    "cyclic-velocities": "Ẋ follows from the conserved p_X and the block's Ḋ.",
    "effective-potential": "At fixed p_X the slide D moves in a linear potential with a reduced inertia; the term p_X²/(2 (M + m)) is a constant (the kinetic energy the conserved momentum locks in), so only −m g D sin α pushes, and it has no minimum.",
    "energy-integral": "Energy at fixed p_X gives Ḋ from D.",
    "time-integral": "The integral gives the uniformly accelerated slide D(t).",
    "equilibria": "A frictionless slope cannot hold the block, so there is none; with p_X held, U_eff′ is a non-zero constant too: the block always slides.",
    "constraints": "With (x₁, z₁) the wedge's top corner and (x₂, z₂) the block, across and up in metres, the block stays on the slope and the wedge on the floor.",
    "multiplier-lagrangian": "Block and wedge free in the plane; λ₁ pushes them apart along the slope's normal, λ₂ holds the wedge on the floor.",
    "multiplier-equation": "The slope's normal involves both bodies, so each λ₁ equation holds both masses.",
    "multiplier": "Both multipliers are constant: the contact and floor forces do not change while the block slides.",
    "constraint-forces": "The wedge's push on the block is less than m g cos α, because the wedge recoils.",
}


ROLLING_CYLINDER_WEDGE: dict[str, str] = {
    "action": "Cylinder and wedge move so that ∫ L dt is stationary between two configurations; every force is constant, so there is no kinetic focus and the true path is a minimum of the action for every duration.",
    "positions": "The wedge's top corner is at X; only its horizontal position changes.",
    "velocities": "The wedge moves along the floor at Ẋ.",
    "squared-speeds": "The wedge's squared speed is Ẋ² alone.",
    "bodies": "The cylinder's centre is s down the slope and r out from it, so it moves with the wedge's Ẋ and its own ṡ along the slope, at angle α to each other; rolling without slipping, it turns at the rate ṡ/r, and a uniform solid cylinder's I_cm is m r²/2.",
    "kinetic": "The centre's motion gives ½ m (Ẋ² + ṡ² + 2 Ẋ ṡ cos α), with the cross term coupling the cylinder to the wedge, and the turning adds ½ (½ m r²)(ṡ/r)² = ¼ m ṡ²: the cylinder's inertia along the slope is 3m/2, not m.",
    "potential": "The cylinder's centre descends s sin α; the wedge's height does not change.",
    "lagrangian": "X appears only through Ẋ: the floor is the same everywhere.",
    "derivatives:X": "∂L/∂X = 0: the horizontal momentum of the pair is conserved.",
    "derivatives:s": "∂L/∂s = m g sin α is gravity along the slope; ∂L/∂ṡ holds the turning's extra ½ m ṡ.",
    "euler-lagrange": "The first says the total horizontal momentum is constant; the second is the roll, with the friction that makes the cylinder turn hidden in the rolling condition.",
    "mass-matrix": "The mass matrix ℳ is not diagonal: rolling the cylinder pushes the wedge back. Its corner 3m/2 is the cylinder's inertia along the slope, m for its centre and m/2 for its turning.",
    "accelerations": "Both accelerations are constant. Halved above and below, s̈ is (M + m) g sin α over M + m sin² α + (M + m)/2: a block sliding on the same wedge has the same numerator over M + m sin² α alone, so the turning adds (M + m)/2 to the denominator, and the cylinder rolls down more slowly and pushes the wedge back less. With the wedge held fixed (M → ∞) s̈ is 2g sin α/3, a block's g sin α.",
    "comparison": "What the statement asks: beside the cylinder, a block sliding without friction on the same wedge (the cylinder with its turning left out) and the wedge held fixed (M → ∞). The block's accelerations have M + m sin² α below, the cylinder's a larger denominator, so the cylinder rolls down more slowly and pushes the wedge back less; on a fixed wedge the cylinder's s̈ is 2g sin α/3, a block's g sin α.",
    "momenta": "p_X = (M + m) Ẋ + m ṡ cos α is the total horizontal momentum; p_s is not conserved, gravity acts along s.",
    "cyclic": "The floor is uniform, so p_X is conserved: starting from rest, the wedge moves back as the cylinder moves forward, their centre of mass staying at the same horizontal place.",
    "time-dependence": "Nothing is driven, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "The wedge's kinetic energy, the cylinder's motion and turning, and the cylinder's gravitational energy, −m g s sin α; rolling without slipping does no work, so no energy is lost.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("the kinetic energy written with the inverse mass matrix, minus m g s sin α"),
    "cyclic-velocities": "Ẋ follows from the conserved p_X and the cylinder's ṡ.",
    "effective-potential": "At fixed p_X the roll s moves in a linear potential with a reduced inertia; the term p_X²/(2 (M + m)) is a constant, so only −m g s sin α pushes, and it has no minimum.",
    "energy-integral": "Energy at fixed p_X gives ṡ from s.",
    "time-integral": "The integral gives the uniformly accelerated roll s(t).",
    "equilibria": "The slope cannot hold the cylinder still, so there is none; with p_X held, U_eff′ is a non-zero constant too: the cylinder always rolls.",
}


ROTATING_PARABOLA: dict[str, str] = {
    "action": "Along the turning wire the bead moves so that ∫ L dt is stationary, the wire's rotation built into L; whether it stays the least for long times depends on whether gravity or the spin wins.",
    "positions": "The bead is at signed horizontal distance ρ from the axis on the parabola z = α ρ² (negative on the other branch), turned by the angle ω t.",
    "velocities": "ρ̇ horizontally in the wire's plane, ω ρ around the axis, and 2 α ρ ρ̇ up.",
    "squared-speeds": "The three directions are perpendicular: (1 + 4 α² ρ²) ρ̇² + ω² ρ².",
    "kinetic": "The motor's turning adds ½ m ω² ρ², a term without ρ̇.",
    "potential": "The bead's height on the parabola is α ρ², so U = m g α ρ².",
    "lagrangian": "The ω² ρ² term acts like a centrifugal potential pushing outward.",
    "derivatives:rho": "∂L/∂ρ holds the centrifugal push m ω² ρ against gravity's 2 m g α ρ.",
    "euler-lagrange": "The sign of 2 g α − ω² decides whether the bottom holds the bead.",
    "mass-matrix": "The wire's slope makes the inertia along it m (1 + 4 α² ρ²).",
    "accelerations": "Near ρ = 0 the bead returns when ω² < 2 g α and runs away when ω² > 2 g α.",
    "momenta": "p_ρ = m (1 + 4 α² ρ²) ρ̇ is the momentum conjugate to ρ, not the bead's momentum along the wire: the bead moves along the wire at the speed √(1 + 4 α² ρ²) ρ̇, so its momentum there is m √(1 + 4 α² ρ²) ρ̇, and p_ρ is that times dℓ/dρ = √(1 + 4 α² ρ²), the length of wire per unit of ρ.",
    "time-dependence": "L has no t: the turning is uniform, so h is conserved.",
    "hamiltonian": "h = T₂ − T₀ + U: the term ½ m ω² ρ² enters with a minus sign.",
    "energy": "E = T + U counts the rotational kinetic energy with a plus sign.",
    "h-vs-e": "The positions depend on t through ω t, so h ≠ E; h is conserved, E is not.",
    **_hamiltonian("p_ρ²/(2 m (1 + 4 α² ρ²)) + m (g α − ω²/2) ρ²"),
    "effective-potential": "Gravity's m g α ρ² minus the centrifugal ½ m ω² ρ², with the inertia of the slope.",
    "energy-integral": "The conserved h gives ρ̇ from ρ.",
    "time-integral": "Taken between the turning points, the integral is half the period of the oscillation along the wire (when ω² < 2 g α).",
    "reduced-equilibria": "The bottom holds the bead with Ω² = 2 g α − ω² when that is positive (Ω, the frequency along the wire; ω is the turning rate).",
    "equilibria": "ρ = 0 is the only equilibrium unless ω² = 2 g α, when every ρ is one. They are the stationary points of the effective potential U_eff, gravity's m g α ρ² less the centrifugal ½ m ω² ρ².",
    "normal-modes": "At the bottom the small oscillations along the wire have Ω² = 2 g α − ω².",
    "constraints": "The wire lies on the paraboloid z = α ρ² and in the plane turned by ω t.",
    "multiplier-lagrangian": "Two multipliers: λ₁ for the paraboloid, λ₂ for the turning plane; the plane's 𝒞₂ holds t.",
    "multiplier-equation": "𝒞₂ depends on t, so its second derivative also holds the terms of the turning: ω and ω² times the position and velocity.",
    "multiplier": "λ₂ = 2mωρ̇ pushes the bead round as it moves along the wire (the Coriolis force, with the sign of the push).",
    "constraint-forces": "The wire pushes normal to itself in its plane and, across it, drives the bead around.",
}


def reason(reasons: Mapping[str, str], key: str) -> str | None:
    """A scene's reason for a step (``reasons``: the scene's own), by the step's key or else by its kind
    (the key's part before a colon)."""
    return reasons.get(key) or reasons.get(key.partition(":")[0])


COUPLED_OSCILLATORS: dict[str, str] = {
    "action": "The two masses move so that ∫ L dt is stationary between two configurations; each mode is a spring-like oscillation, so past half the faster mode's period the true path is a saddle of S, not its least value.",
    "positions": "Both masses stay on the line; each sits at its rest position (a distance d either side of the middle) plus its displacement.",
    "velocities": "A rest position does not move, so each mass's velocity is the rate of its own displacement.",
    "squared-speeds": "On a line each squared speed is just ẋ², with no term mixing the two masses.",
    "kinetic": "The two equal masses' kinetic energies add, and neither velocity is tied to the other.",
    "potential": "The outer springs are stretched by x₁ and x₂; the middle one by x₂ − x₁, its ends' difference in displacement.",
    "lagrangian": "The masses are coupled only through the middle spring's term: with κ = 0 L splits into two separate oscillators.",
    "derivatives:x1": "∂L/∂x₁ is the net spring force on mass 1: the left spring pulls it back by k x₁, the middle spring by κ (x₁ − x₂); ∂L/∂ẋ₁ = m ẋ₁ is its momentum.",
    "derivatives:x2": "Mass 2 feels the mirror image: the right spring's −k x₂ and the middle spring's pull κ (x₁ − x₂), equal and opposite to the one on mass 1.",
    "euler-lagrange": "Newton's law for each mass: two linear equations, coupled through κ alone.",
    "mass-matrix": "ℳ is diagonal, m and m: the masses are coupled through the middle spring's force, not through their inertia.",
    "accelerations": "Each acceleration is the net spring force on that mass over m; it depends on the other mass's displacement through κ.",
    "momenta": "p_x₁ = m ẋ₁ and p_x₂ = m ẋ₂ are the masses' ordinary momenta; the walls take up momentum, so their sum is not conserved.",
    "time-dependence": "Walls and springs stay put, so L has no t.",
    "hamiltonian": "T is quadratic in the velocities, so h is T + U.",
    "energy": "The two masses' kinetic energies plus the energy stored in all three springs.",
    "h-vs-e": _h_is_e("The rest positions do not depend on t"),
    **_hamiltonian("(p_x₁² + p_x₂²)/(2m) + ½ k x₁² + ½ k x₂² + ½ κ (x₂ − x₁)²"),
    "equilibria": "These are all the equilibria: the net force on each mass is linear in the displacements, and with the walls holding the outer springs it vanishes only when both masses are at rest positions, x₁ = x₂ = 0.",
}


DOUBLE_PENDULUM: dict[str, str] = {
    "action": "Both rods swing so that ∫ L dt is stationary between any two configurations of the rods a time τ apart.",
    "positions": "The first bob is l₁ from the pivot at θ₁; the second is l₂ further on at θ₂, both angles from the downward vertical and the pivot at the origin.",
    "velocities": "The second bob's velocity adds its own swing about the first bob to the first bob's velocity.",
    "squared-speeds": "The first bob moves on a circle, l₁² θ̇₁²; the second bob's two velocities at angle θ₁ − θ₂ to each other add a cross term 2 l₁ l₂ θ̇₁ θ̇₂ cos(θ₁ − θ₂).",
    "kinetic": "The lower bob's cross term couples the two swings through their inertia: T is not a sum of two pendulums.",
    "potential": "Both bobs hang below the pivot: the first by l₁ cos θ₁, the second by l₁ cos θ₁ + l₂ cos θ₂, so the first rod carries both masses' weight.",
    "lagrangian": "T − U; the coupling sits in the kinetic energy, through cos(θ₁ − θ₂), not in the potential.",
    "derivatives:theta1": "∂L/∂θ₁ is gravity's torque on the two bobs about the pivot plus the cross term's dependence on θ₁; ∂L/∂θ̇₁ counts both bobs' inertia (m₁ + m₂) l₁² and, through the cross term, the lower bob's swing.",
    "derivatives:theta2": "∂L/∂θ₂ is gravity's torque on the lower bob about the upper one, with the cross term again; ∂L/∂θ̇₂ is the lower bob's angular momentum about the upper bob, taken with its full velocity.",
    "euler-lagrange": "Two equations, each containing both angular accelerations: the upper rod's swing drives the lower one and the lower one pulls back on the upper.",
    "mass-matrix": "ℳ has the off-diagonal m₂ l₁ l₂ cos(θ₁ − θ₂): the two rods' inertia is coupled, most strongly when they are in line.",
    "accelerations": "Solving the two equations for θ̈₁ and θ̈₂ gives their long explicit form; it is what the simulation integrates.",
    "momenta": "p_θ₁ and p_θ₂ mix both angular velocities through cos(θ₁ − θ₂); neither is conserved, since gravity exerts a torque on each rod.",
    "time-dependence": "Pivot and rods are fixed, so L has no t.",
    "hamiltonian": "T is quadratic in the angular velocities, so h is T + U.",
    "energy": "Both bobs' kinetic energy plus their gravitational energy, measured from the pivot's height.",
    "h-vs-e": _h_is_e("The pivot does not move"),
    **_hamiltonian("the kinetic energy rewritten in p_θ₁ and p_θ₂, plus the same U"),
    "equilibria": "These are all the equilibria: at rest the torques vanish only where sin θ₁ = 0 and sin θ₂ = 0, that is with each rod straight down or straight up, four combinations.",
    # U = −(m₁ + m₂) g l₁ cos θ₁ − m₂ g l₂ cos θ₂ with positive inertia: one ω² < 0 per direction in which U falls
    "normal-modes:2": "The lower rod stands upright on the hanging upper one: U falls if the lower rod tips, so one ω² is negative and the equilibrium is unstable.",
    "normal-modes:3": "The upper rod stands upright with the lower one hanging from its top: U falls if the upper rod tips, so again one ω² is negative: unstable.",
    "normal-modes:4": "Both rods upright in line: U is at its highest, both ω² are negative, and a small push along either mode grows.",
}


PHYSICAL_PENDULUM: dict[str, str] = {
    "action": "Of all the ways the rod could swing from one angle to another in the same time, the real swing makes ∫ (T − U) dt stationary.",
    "bodies": "The centre of mass is halfway down the rod, l/2 from the pivot, so it moves on a circle at speed (l/2) θ̇; the rod turns at the rate θ̇, and a uniform rod's I_cm is M l²/12.",
    "kinetic": "The centre's motion gives ½ M (l/2)² θ̇² = M l² θ̇²/8 and the turning about the centre M l² θ̇²/24; together M l² θ̇²/6, which is ½ I θ̇² with I = M l²/3 about the pivot.",
    "potential": "The centre of mass is (l/2) cos θ below the pivot, so U = −½ M g l cos θ: the whole weight acts at the centre.",
    "lagrangian": "T − U with one coordinate, as for the simple pendulum, but with the rod's own moment of inertia.",
    "derivatives:theta": "∂L/∂θ = −½ M g l sin θ is gravity's torque about the pivot; ∂L/∂θ̇ = M l² θ̇/3 is the rod's angular momentum about it.",
    "euler-lagrange": "Angular momentum about the pivot changes at the rate of the torque; divided by M l²/3 the mass drops out.",
    "mass-matrix": "One coordinate: ℳ is the moment of inertia about the pivot, M l²/3, and f is the torque −½ M g l sin θ.",
    "accelerations": "θ̈ = −(3g/2l) sin θ: a simple pendulum of length 2l/3 swings the same way.",
    "momenta": "p_θ = M l² θ̇/3 is the rod's angular momentum about the pivot.",
    "time-dependence": "Nothing in the set-up moves or changes with time, so L has no t in it.",
    "hamiltonian": "T is quadratic in θ̇, so h is T + U.",
    "energy": "The rod's kinetic energy plus the gravitational energy of its weight at the centre.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("3 p_θ²/(2 M l²) − ½ M g l cos θ"),
    "effective-potential": "With a single coordinate there is nothing to fold in: U_eff is U itself.",
    "energy-integral": "Energy conservation gives θ̇ as a function of θ, one integration from the motion.",
    "time-integral": "Taken between the turning points, this integral is half the period of a wide swing: an elliptic integral, as for the simple pendulum.",
    "reduced-equilibria": "The rod hanging down (θ = 0) is stable with ω² = 3g/(2l); standing up (θ = π) it is unstable.",
    "equilibria": "sin θ = 0 with the rod straight down or straight up, and nowhere else.",
    "normal-modes": "Linearising sin θ about each equilibrium gives ω² = 3g/(2l) hanging down and −3g/(2l) standing up.",
}


MASSIVE_PULLEY: dict[str, str] = {
    "action": "The masses and the pulley move so that ∫ (T − U) dt is stationary between two positions; every force is a constant weight, so there is no kinetic focus and the true motion is a minimum of the action for every duration.",
    "positions": "The string hangs from the two sides of the rim, R either side of the axle: m₂ has gone up by z and, the string being inextensible, m₁ down by as much.",
    "velocities": "Both masses move vertically at the string's speed ż, m₂ up and m₁ down.",
    "squared-speeds": "Each mass moves at ż, so each squared speed is ż².",
    "bodies": "The pulley's centre is on the fixed axle, so it does not move; the string does not slip, so the rim moves at ż and the disc turns at ż/R; a uniform disc's I_cm is M R²/2.",
    "kinetic": "The masses give ½ m₁ ż² + ½ m₂ ż²; the pulley only turns, ½ (½ M R²)(ż/R)² = ¼ M ż²: R drops out, and the pulley counts as a mass M/2 moving with the string.",
    "potential": "m₂ is z higher and m₁ z lower than at the start; the pulley's centre stays at the axle, so its weight adds nothing that changes.",
    "lagrangian": "T − U with one coordinate: the string and the pulley's grip on it leave the whole machine a single degree of freedom.",
    "derivatives:z": "∂L/∂z = (m₁ − m₂) g is the net weight pulling the string m₁'s way; ∂L/∂ż is the momentum of the masses plus the pulley's angular momentum ½ M R² (ż/R) divided by R.",
    "euler-lagrange": "The net weight (m₁ − m₂) g accelerates all three: the masses with their full m₁ + m₂, the pulley with M/2.",
    "mass-matrix": "One coordinate: ℳ = m₁ + m₂ + M/2 is the machine's inertia along the string, and f = (m₁ − m₂) g the net weight.",
    "accelerations": "z̈ = (m₁ − m₂) g/(m₁ + m₂ + M/2), a constant: the net weight over the machine's inertia along the string.",
    "limits": "As M → 0 the pulley's turning drops out and the massless pulley's (m₁ − m₂) g/(m₁ + m₂) comes back; any M adds M/2 to the inertia the net weight pulls, so a massive pulley slows the machine, and its radius does not matter.",
    "momenta": "p_z = (m₁ + m₂ + M/2) ż: the masses' momenta along the string plus the pulley's angular momentum about the axle divided by R.",
    "time-dependence": "The axle is fixed and nothing in the set-up changes with time, so L has no t in it.",
    "hamiltonian": "T is quadratic in ż, so h is T + U.",
    "energy": "The kinetic energy of the masses and of the pulley's turning, plus the masses' gravitational energy.",
    "h-vs-e": _h_is_e("The positions do not depend on t"),
    **_hamiltonian("p_z²/(2 (m₁ + m₂ + M/2)) + (m₂ − m₁) g z"),
    "effective-potential": "With a single coordinate there is nothing to fold in: U_eff is U itself, a straight line in z, and the effective mass m₁ + m₂ + M/2.",
    "energy-integral": "Energy conservation gives ż as a function of z: from rest the speed grows as the square root of the distance run, as under any constant force.",
    "time-integral": "From rest the integral gives z = ½ z̈ t², the motion under the constant acceleration found above.",
    "equilibria": "U changes at the constant rate (m₂ − m₁) g: with unequal masses there is no equilibrium, and with m₁ = m₂ every position is one.",
}
