// Homework 8 in JavaScript, done as the exercise asks: semi-implicit Euler with a global drag on
// each mass, and Verlet with its damping factor. The browser's checks type this into the panel.
function springForces(rope) {
  for (const s of rope.springs) {
    const d = s.m2.position.minus(s.m1.position);
    const f = d.unit().times(s.k * (d.norm() - s.rest_length));
    s.m1.forces = s.m1.forces.plus(f);
    s.m2.forces = s.m2.forces.minus(f);
  }
}

function simulateEuler(rope, delta_t, gravity) {
  springForces(rope);
  for (const m of rope.masses) {
    if (!m.pinned) {
      m.forces = m.forces.plus(gravity.times(m.mass)).minus(m.velocity.times(0.02));
      m.velocity = m.velocity.plus(m.forces.over(m.mass).times(delta_t));
      m.position = m.position.plus(m.velocity.times(delta_t));
    }
    m.forces = new Vector2D(0, 0);
  }
}

function simulateVerlet(rope, delta_t, gravity) {
  springForces(rope);
  for (const m of rope.masses) {
    if (!m.pinned) {
      const temp_position = m.position;
      const a = m.forces.over(m.mass).plus(gravity);
      m.position = m.position.plus(m.position.minus(m.last_position).times(1 - 0.00005)).plus(a.times(delta_t * delta_t));
      m.last_position = temp_position;
    }
    m.forces = new Vector2D(0, 0);
  }
}
