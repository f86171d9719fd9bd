#!/usr/bin/python3
"""The step impulse's two closures on one rigid mass sliding on a friction
base under a harmonic base acceleration (doc/joints-in-time.md, "The
closures at a friction turn"; doc/theory/joints.md §11).

The mass is the rigid block of tests/joint_sliding.cc's harmonic case
(a_g = A g sin(2 pi t / T), A = 0.4, T = 0.5 s, friction coefficient 0.2,
1 s). Relative to the base it obeys s'' = -a_g + f, |f| <= mu g, f opposing
the slip while it slides. Three solutions:

  reference    event by event with exact sub-steps of dt / 1000: the mass
               sticks while |a_g| <= mu g, slides with the friction against
               its velocity, stops where its velocity vanishes;
  dissipative  one force per step (the step impulse with the average
               acceleration rule: v1 = v + dt (a + f), s1 = s + dt/2 (v + v1),
               a the step's mean of -a_g): sticking holds the position
               (s1 = s, hence v1 = -v), slipping puts the friction against
               the step's increment s1 - s;
  velocities   sticking holds the velocity at zero (v1 = 0), slipping puts
               the friction against the velocity at the step's end;
  split        dissipative, but a step in which the sliding mass turns
               (its velocity would change sign under the friction against
               it while |a| > mu g) has the friction against the velocity
               until it vanishes and against the new slip after;
  split, rest  split, and a held step ends at rest (v1 = 0: the position
               held, the velocity that holding it would reverse taken out,
               a loss of kinetic energy);
  turn first   one force per step as the program's step has it (the
               position by the trapezoidal rule, s1 = s + dt/2 (v + v1)),
               the turn tested before the held branch: a step in which the
               sliding mass turns takes the turn's impulse, the friction
               against v for theta dt and against the new slip after, its
               mean mu g (1 - 2 theta) against v; otherwise dissipative;
  turn if loss turn first, but the turn's impulse only where its work in
               the step, f (s1 - s), is a loss (else dissipative), and a
               held step ends at rest.

For the last two it also prints the friction's positive work in the steps
(the sum of f (s1 - s) where it is positive, per unit mass, as a share of
the friction's whole loss over the run, the sum of -f (s1 - s)), the
energy that one force per step can create at a turn: the turn's impulse
is exact, its work with the trapezoidal position is not.

It prints, for each rule, the largest |s - reference| over the run as a
share of the peak slip, at 1, 0.5 and 0.25 ms (the test's steps are the
first two) and, since the error of a step depends on where in the step the
events fall, its mean and largest over eight steps in [dt, 1.5 dt) (split
alone: at 1 and 0.5 ms); then, at 1 ms, the error before and after the
first turn (the block's velocity changing sign without a stick phase, near
0.3 s), to show where it enters.
"""
import math
import statistics

G, MU, A, T, END = 9.81, 0.2, 0.4, 0.5, 1.0


def ground(t):
    return A * G * math.sin(2 * math.pi * t / T)


def reference(dt):
    h = dt / 1000
    s, v, t, out = 0.0, 0.0, 0.0, [0.0]
    for _ in range(round(END / dt)):
        for _ in range(1000):
            a = -ground(t + 0.5 * h)
            if v == 0.0:
                if abs(a) <= MU * G:
                    t += h
                    continue
                acc = a - MU * G * math.copysign(1, a)
            else:
                acc = a - MU * G * math.copysign(1, v)
            v1 = v + h * acc
            if v != 0.0 and v1 * v < 0:  # stops within the sub-step
                s += 0.5 * v * h * v / (v - v1)
                v = 0.0
            else:
                s += 0.5 * (v + v1) * h
                v = v1
            t += h
        out.append(s)
    return out


def turning(v, a, dt):
    """(sign of v, theta) when the sliding mass turns in the step (its
    velocity would change sign under the friction against it while
    |a| > mu g), the friction against v for theta dt; else None."""
    if v == 0.0 or abs(a) <= MU * G:
        return None
    sign = math.copysign(1, v)
    if (v + dt * (a - MU * G * sign)) * v >= 0:
        return None
    return sign, -v / (a - MU * G * sign) / dt


def turn(s, v, a, dt):
    """The turning step's impulse with the trapezoidal position, or None
    when the sliding mass does not turn in the step: (s1, v1, f)."""
    turns = turning(v, a, dt)
    if turns is None:
        return None
    sign, theta = turns
    f = MU * G * sign * (1 - 2 * theta)
    v1 = v + dt * (a + f)
    return s + 0.5 * dt * (v + v1), v1, f


def stepped(dt, rule):
    s, v, t, out = 0.0, 0.0, 0.0, [0.0]
    stepped.positive_work, stepped.loss = 0.0, 0.0
    for _ in range(round(END / dt)):
        a = -0.5 * (ground(t) + ground(t + dt))
        turned = turn(s, v, a, dt) if rule.startswith("turn") else None
        if turned and (rule == "turn first" or turned[2] * (turned[0] - s) <= 0):
            s1, v1, f = turned
            step_work(f, s1 - s)
            s, v, t = s1, v1, t + dt
            out.append(s)
            continue
        held_v = 0.0 if rule == "velocities" else -v
        f = (held_v - v) / dt - a  # the force that sticks
        if abs(f) <= MU * G:
            v1 = held_v
            s1 = s + 0.5 * dt * (v + v1)
            if rule in ("split, rest", "turn if loss"):
                v1 = 0.0
        elif rule.startswith("split") and turning(v, a, dt):
            # the mass turns: the friction against v until it vanishes
            # (theta dt), then against the new slip
            sign, theta = turning(v, a, dt)
            v1 = (1 - theta) * dt * (a + MU * G * sign)
            s1 = s + 0.5 * v * theta * dt + 0.5 * v1 * (1 - theta) * dt
        else:
            for sign in (1, -1):  # the friction against the increment or the end velocity
                v1 = v + dt * (a - MU * G * sign)
                along = v1 if rule == "velocities" else 0.5 * (v + v1)
                if along * sign > 0:
                    break
            s1 = s + 0.5 * dt * (v + v1)
            step_work(-MU * G * sign, s1 - s)
        s, v, t = s1, v1, t + dt
        out.append(s)
    return out


def step_work(f, ds):
    """Books the friction's work f ds of a step (turn rules)."""
    stepped.positive_work += max(0.0, f * ds)
    stepped.loss += max(0.0, -f * ds)


def error(dt, rule):
    r, x = reference(dt), stepped(dt, rule)
    peak = max(abs(y) for y in r)
    return max(abs(p - q) for p, q in zip(x, r)) / peak, r, x, peak


def main():
    for rule in ("dissipative", "velocities", "split, rest"):
        print(f"{rule}: max |s - reference| / peak slip")
        for dt in (1e-3, 5e-4, 2.5e-4):
            e = [error(dt * (1 + k / 16), rule)[0] for k in range(8)]
            print(f"  dt = {dt * 1e3:5.3f} ms: {100 * e[0]:.2f} %;"
                  f" over [dt, 1.5 dt): mean {100 * statistics.mean(e):.2f} %,"
                  f" largest {100 * max(e):.2f} %")
    for rule in ("turn first", "turn if loss"):
        print(f"{rule}: max |s - reference| / peak slip; the friction's positive work")
        for dt in (1e-3, 5e-4, 2.5e-4):
            e, w = [], []
            for k in range(8):
                e.append(error(dt * (1 + k / 16), rule)[0])
                w.append(stepped.positive_work / stepped.loss)
            print(f"  dt = {dt * 1e3:5.3f} ms: {100 * e[0]:.2f} %;"
                  f" over [dt, 1.5 dt): mean {100 * statistics.mean(e):.2f} %,"
                  f" largest {100 * max(e):.2f} %; positive work at most {max(w):.1e} of the loss")
    print("split: max |s - reference| / peak slip")
    for dt in (1e-3, 5e-4):
        print(f"  dt = {dt * 1e3:5.3f} ms: {100 * error(dt, 'split')[0]:.2f} %")
    print("where the error enters (dt = 1 ms), (s - reference) / peak slip:")
    for rule in ("dissipative", "velocities"):
        _, r, x, peak = error(1e-3, rule)
        print(f"  {rule}: " + ", ".join(f"t = {t:.2f} s {100 * (x[round(t / 1e-3)] - r[round(t / 1e-3)]) / peak:+.2f} %"
                                        for t in (0.29, 0.33, 0.6, 1.0)))


if __name__ == "__main__":
    main()
