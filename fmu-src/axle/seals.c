/* Lip-seal friction (seals.h for the source). */
#include "axle/seals.h"

#include "io/constants.h"

double hg_seal_torque(double d_sh)
{
    double d_mm = d_sh * 1e3;
    /* P = 7.69e-6 d^2 n [W] with n = omega 30/pi  =>  T = P/omega = 7.69e-6 d^2 30/pi [N m] */
    return 7.69e-6 * d_mm * d_mm * 30.0 / HG_PI;
}
