/* Mathematical constants, defined once for every layer (the bottom layer, so that any file may
 * include it). Literals with more digits than a double holds: each rounds to the double nearest
 * the exact value. */
#ifndef HG_CONSTANTS_H
#define HG_CONSTANTS_H

#define HG_PI 3.14159265358979323846
#define HG_TWO_PI 6.28318530717958647693
#define HG_RPM_PER_RAD_S (30.0 / HG_PI) /* [rpm] per [rad/s] */

#endif
