"""From a declaration to T, U, L and the equations of motion, and what follows from them: conservation,
the reduction to one coordinate, Hamilton's equations, the forces of constraint, new coordinates."""
