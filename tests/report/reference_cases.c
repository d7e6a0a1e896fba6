/* The free-motion scenes of tests/reference.c as report cases. */
#include <math.h>
#include "report.h"

static reference_result_t diagnose(const report_case_t *c, integrator_t integrator, double h) {
    return reference_run((reference_scene_t)c->which, integrator, h, c->periods);
}

static void *build(const report_case_t *c, integrator_t integrator, double h) {
    return reference_start((reference_scene_t)c->which, integrator, h);
}

static scene_t *scene_of(void *run) {
    return reference_get_scene(run);
}

static vector_t end_centroid(void *run) {
    return reference_tracked_centroid(run);
}

static void finish(void *run) {
    reference_finish(run);
}

static report_case_t reference_case(reference_scene_t scene, const char *title, double periods,
                                    double first_h) {
    report_case_t c = {reference_name(scene), title, reference_error_name(scene), "", first_h,
                       (int)scene, periods, 0, diagnose, build, scene_of, end_centroid, finish,
                       NULL};
    double period = reference_period(scene);
    if (scene == REFERENCE_BOUNCE) {
        snprintf(c.span, sizeof c.span, "to the fifth apex");
    } else if (period == 1.0) {
        snprintf(c.span, sizeof c.span, "after %g s", periods);
    } else {
        snprintf(c.span, sizeof c.span, "after %.4g s (%g periods of %.4g s)", periods * period,
                 periods, period);
    }
    return c;
}

int report_reference_cases(report_case_t *cases, int capacity, bool quick) {
    const double kepler = reference_period(REFERENCE_KEPLER);
    const double orbit = reference_period(REFERENCE_ORBIT);
    const double periods = quick ? 1.25 : 10.25;
    report_case_t list[] = {
        reference_case(REFERENCE_OSCILLATOR,
                       "a 1 kg body on a spring k = (2 pi)^2 N/m to an anchor of infinite mass, "
                       "x0 = 1 m, v0 = pi m/s: x(t) = x0 cos wt + (v0 / w) sin wt, w = 2 pi rad/s. "
                       "Error in phase space, sqrt(dx^2 + (dv / w)^2) over the amplitude: at whole "
                       "periods symplectic Euler's first-order error cancels (it is Verlet seen "
                       "through a half kick, which changes velocities only), so the run ends a "
                       "quarter period later",
                       periods, 1.0 / 8.0),
        reference_case(REFERENCE_KEPLER,
                       "eccentricity 0.6, a 0.001 kg body around a 1 kg one under "
                       "create_newtonian_gravity with G (m1 + m2) = 1, centre of mass at rest; the "
                       "relative motion starts at pericentre, q0 = (1 - e, 0), p0 = (0, sqrt((1 + "
                       "e) / (1 - e))), energy -1/2 per unit reduced mass, period 2 pi. Exact: "
                       "Kepler's equation solved by Newton for the change of eccentric anomaly, "
                       "then Lagrange's f and g. Error: the relative position over the semi-major "
                       "axis and the velocity over sqrt(mu / a), in one norm",
                       periods, kepler / 32.0),
        reference_case(REFERENCE_KEPLER_ECCENTRIC,
                       "kepler at eccentricity 0.9: pericentre 0.1, apocentre 1.9, the speed at "
                       "pericentre 19 times that at apocentre",
                       periods, kepler / 128.0),
        reference_case(REFERENCE_ORBIT,
                       "the orbit scene of [bench-scenes.md](bench-scenes.md) (G = 1, 1000 kg at "
                       "the origin, 1 kg at (10, 0) m with (0, 10) m/s: nearly circular), measured "
                       "as kepler",
                       periods, orbit / 32.0),
        reference_case(REFERENCE_DRAG,
                       "a 1 kg projectile from (0, 0) at (10, 10) m/s under gravity (0, -9.81) and "
                       "create_drag with b = 0.5 /s: v = v_inf + (v0 - v_inf) e^(-bt), x = x0 + "
                       "v_inf t + (v0 - v_inf) (1 - e^(-bt)) / b, v_inf = g / b. Error: position "
                       "over the distance flown",
                       quick ? 1.0 : 5.0, 0.5),
        reference_case(REFERENCE_BOUNCE,
                       "the bounce scene of [bench-scenes.md](bench-scenes.md) with world "
                       "contacts: a 1 m box from 10 m at elasticity 0.8 under g = 10; apex n "
                       "at 10 e^(2n) m. Error: the largest relative apex error over five bounces, each apex from "
                       "the parabola through the last rising step",
                       1.0, 1.0 / 15.0),
    };
    int count = 0;
    for (size_t i = 0; i < sizeof list / sizeof list[0] && count < capacity; i++) {
        cases[count++] = list[i];
    }
    return count;
}
