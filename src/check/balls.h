/* balls.h — balls and radii as short decimal text, for the messages of the
 * checker and its text and JSON reports. */
#ifndef VIGEN_CHECK_BALLS_H
#define VIGEN_CHECK_BALLS_H

#include <arb.h>

/* Digits enough to see the difference between x and y in their decimal
 * text (8 .. VIGEN_BALL_MAX_SEPARATING_DIGITS). */
#define VIGEN_BALL_MAX_SEPARATING_DIGITS 2000
slong vigen_ball_digits_to_separate(const arb_t x, const arb_t y, slong prec);

/* The `digits` digits of x when they are certain, otherwise the interval
 * "[lo, hi]" that contains x (rounded outward), so that a reader sees at once
 * whether the ball contains 0.  Heap string. */
char *vigen_ball_str(const arb_t x, slong digits);

/* x as vigen_ball_str does with the digits that tell it from y; when x's
 * digits are not all certain, its bounds (rounded outward) with as many
 * digits, so that a bound that excludes y does not print as y.  Heap string. */
char *vigen_ball_str_apart(const arb_t x, const arb_t y, slong prec);

/* arb's "[mid +/- rad]" with the midpoint always shown, for JSON.  Heap string. */
char *vigen_ball_json_str(const arb_t x, slong digits);

/* An upper bound of m as a 2-digit decimal rounded up.  Heap string. */
char *vigen_mag_str(const mag_t m);

#endif
