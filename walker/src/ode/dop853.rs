//! Dormand–Prince 8(5,3) with the 7th-order dense output.
//!
//! Coefficients copied digit for digit from E. Hairer's `dop853.f` (version
//! of April 25, 1996, small corrections March 4, 2002; subroutine `DP86CO`),
//! described in E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., Springer 1993, Sect. II.5 (method) and
//! II.6 (dense output). The literals keep all published digits.
//!
//! A step costs 12 stages (11 new evaluations, the first being the previous
//! step's last one) plus `f(t + h, y_new)` after acceptance. The error
//! estimate combines the 5th- and 3rd-order embedded solutions as in
//! Hairer's code. The dense output needs three extra stages (14, 15, 16); they
//! are only computed for steps where the interpolant is actually used.
// Literals keep the published digits; stage formulas index the stage
// vectors explicitly, mirroring the published Fortran loops.
#![allow(clippy::excessive_precision, clippy::needless_range_loop)]

use super::options::Tolerances;
use super::stats::Stats;
use super::stepper::{ControlKind, Dense, Stepper, rhs};
use super::system::OdeSystem;

const C2: f64 = 0.526001519587677318785587544488e-01;
const C3: f64 = 0.789002279381515978178381316732e-01;
const C4: f64 = 0.118350341907227396726757197510e+00;
const C5: f64 = 0.281649658092772603273242802490e+00;
const C6: f64 = 0.333333333333333333333333333333e+00;
const C7: f64 = 0.25e+00;
const C8: f64 = 0.307692307692307692307692307692e+00;
const C9: f64 = 0.651282051282051282051282051282e+00;
const C10: f64 = 0.6e+00;
const C11: f64 = 0.857142857142857142857142857142e+00;
const C14: f64 = 0.1e+00;
const C15: f64 = 0.2e+00;
const C16: f64 = 0.777777777777777777777777777778e+00;

const B1: f64 = 5.42937341165687622380535766363e-2;
const B6: f64 = 4.45031289275240888144113950566e0;
const B7: f64 = 1.89151789931450038304281599044e0;
const B8: f64 = -5.8012039600105847814672114227e0;
const B9: f64 = 3.1116436695781989440891606237e-1;
const B10: f64 = -1.52160949662516078556178806805e-1;
const B11: f64 = 2.01365400804030348374776537501e-1;
const B12: f64 = 4.47106157277725905176885569043e-2;

const BHH1: f64 = 0.244094488188976377952755905512e+00;
const BHH2: f64 = 0.733846688281611857341361741547e+00;
const BHH3: f64 = 0.220588235294117647058823529412e-01;

const ER1: f64 = 0.1312004499419488073250102996e-01;
const ER6: f64 = -0.1225156446376204440720569753e+01;
const ER7: f64 = -0.4957589496572501915214079952e+00;
const ER8: f64 = 0.1664377182454986536961530415e+01;
const ER9: f64 = -0.3503288487499736816886487290e+00;
const ER10: f64 = 0.3341791187130174790297318841e+00;
const ER11: f64 = 0.8192320648511571246570742613e-01;
const ER12: f64 = -0.2235530786388629525884427845e-01;

const A21: f64 = 5.26001519587677318785587544488e-2;
const A31: f64 = 1.97250569845378994544595329183e-2;
const A32: f64 = 5.91751709536136983633785987549e-2;
const A41: f64 = 2.95875854768068491816892993775e-2;
const A43: f64 = 8.87627564304205475450678981324e-2;
const A51: f64 = 2.41365134159266685502369798665e-1;
const A53: f64 = -8.84549479328286085344864962717e-1;
const A54: f64 = 9.24834003261792003115737966543e-1;
const A61: f64 = 3.7037037037037037037037037037e-2;
const A64: f64 = 1.70828608729473871279604482173e-1;
const A65: f64 = 1.25467687566822425016691814123e-1;
const A71: f64 = 3.7109375e-2;
const A74: f64 = 1.70252211019544039314978060272e-1;
const A75: f64 = 6.02165389804559606850219397283e-2;
const A76: f64 = -1.7578125e-2;

const A81: f64 = 3.70920001185047927108779319836e-2;
const A84: f64 = 1.70383925712239993810214054705e-1;
const A85: f64 = 1.07262030446373284651809199168e-1;
const A86: f64 = -1.53194377486244017527936158236e-2;
const A87: f64 = 8.27378916381402288758473766002e-3;
const A91: f64 = 6.24110958716075717114429577812e-1;
const A94: f64 = -3.36089262944694129406857109825e0;
const A95: f64 = -8.68219346841726006818189891453e-1;
const A96: f64 = 2.75920996994467083049415600797e1;
const A97: f64 = 2.01540675504778934086186788979e1;
const A98: f64 = -4.34898841810699588477366255144e1;
const A101: f64 = 4.77662536438264365890433908527e-1;
const A104: f64 = -2.48811461997166764192642586468e0;
const A105: f64 = -5.90290826836842996371446475743e-1;
const A106: f64 = 2.12300514481811942347288949897e1;
const A107: f64 = 1.52792336328824235832596922938e1;
const A108: f64 = -3.32882109689848629194453265587e1;
const A109: f64 = -2.03312017085086261358222928593e-2;

const A111: f64 = -9.3714243008598732571704021658e-1;
const A114: f64 = 5.18637242884406370830023853209e0;
const A115: f64 = 1.09143734899672957818500254654e0;
const A116: f64 = -8.14978701074692612513997267357e0;
const A117: f64 = -1.85200656599969598641566180701e1;
const A118: f64 = 2.27394870993505042818970056734e1;
const A119: f64 = 2.49360555267965238987089396762e0;
const A1110: f64 = -3.0467644718982195003823669022e0;
const A121: f64 = 2.27331014751653820792359768449e0;
const A124: f64 = -1.05344954667372501984066689879e1;
const A125: f64 = -2.00087205822486249909675718444e0;
const A126: f64 = -1.79589318631187989172765950534e1;
const A127: f64 = 2.79488845294199600508499808837e1;
const A128: f64 = -2.85899827713502369474065508674e0;
const A129: f64 = -8.87285693353062954433549289258e0;
const A1210: f64 = 1.23605671757943030647266201528e1;
const A1211: f64 = 6.43392746015763530355970484046e-1;

const A141: f64 = 5.61675022830479523392909219681e-2;
const A147: f64 = 2.53500210216624811088794765333e-1;
const A148: f64 = -2.46239037470802489917441475441e-1;
const A149: f64 = -1.24191423263816360469010140626e-1;
const A1410: f64 = 1.5329179827876569731206322685e-1;
const A1411: f64 = 8.20105229563468988491666602057e-3;
const A1412: f64 = 7.56789766054569976138603589584e-3;
const A1413: f64 = -8.298e-3;

const A151: f64 = 3.18346481635021405060768473261e-2;
const A156: f64 = 2.83009096723667755288322961402e-2;
const A157: f64 = 5.35419883074385676223797384372e-2;
const A158: f64 = -5.49237485713909884646569340306e-2;
const A1511: f64 = -1.08347328697249322858509316994e-4;
const A1512: f64 = 3.82571090835658412954920192323e-4;
const A1513: f64 = -3.40465008687404560802977114492e-4;
const A1514: f64 = 1.41312443674632500278074618366e-1;
const A161: f64 = -4.28896301583791923408573538692e-1;
const A166: f64 = -4.69762141536116384314449447206e0;
const A167: f64 = 7.68342119606259904184240953878e0;
const A168: f64 = 4.06898981839711007970213554331e0;
const A169: f64 = 3.56727187455281109270669543021e-1;
const A1613: f64 = -1.39902416515901462129418009734e-3;
const A1614: f64 = 2.9475147891527723389556272149e0;
const A1615: f64 = -9.15095847217987001081870187138e0;

const D41: f64 = -0.84289382761090128651353491142e+01;
const D46: f64 = 0.56671495351937776962531783590e+00;
const D47: f64 = -0.30689499459498916912797304727e+01;
const D48: f64 = 0.23846676565120698287728149680e+01;
const D49: f64 = 0.21170345824450282767155149946e+01;
const D410: f64 = -0.87139158377797299206789907490e+00;
const D411: f64 = 0.22404374302607882758541771650e+01;
const D412: f64 = 0.63157877876946881815570249290e+00;
const D413: f64 = -0.88990336451333310820698117400e-01;
const D414: f64 = 0.18148505520854727256656404962e+02;
const D415: f64 = -0.91946323924783554000451984436e+01;
const D416: f64 = -0.44360363875948939664310572000e+01;

const D51: f64 = 0.10427508642579134603413151009e+02;
const D56: f64 = 0.24228349177525818288430175319e+03;
const D57: f64 = 0.16520045171727028198505394887e+03;
const D58: f64 = -0.37454675472269020279518312152e+03;
const D59: f64 = -0.22113666853125306036270938578e+02;
const D510: f64 = 0.77334326684722638389603898808e+01;
const D511: f64 = -0.30674084731089398182061213626e+02;
const D512: f64 = -0.93321305264302278729567221706e+01;
const D513: f64 = 0.15697238121770843886131091075e+02;
const D514: f64 = -0.31139403219565177677282850411e+02;
const D515: f64 = -0.93529243588444783865713862664e+01;
const D516: f64 = 0.35816841486394083752465898540e+02;

const D61: f64 = 0.19985053242002433820987653617e+02;
const D66: f64 = -0.38703730874935176555105901742e+03;
const D67: f64 = -0.18917813819516756882830838328e+03;
const D68: f64 = 0.52780815920542364900561016686e+03;
const D69: f64 = -0.11573902539959630126141871134e+02;
const D610: f64 = 0.68812326946963000169666922661e+01;
const D611: f64 = -0.10006050966910838403183860980e+01;
const D612: f64 = 0.77771377980534432092869265740e+00;
const D613: f64 = -0.27782057523535084065932004339e+01;
const D614: f64 = -0.60196695231264120758267380846e+02;
const D615: f64 = 0.84320405506677161018159903784e+02;
const D616: f64 = 0.11992291136182789328035130030e+02;

const D71: f64 = -0.25693933462703749003312586129e+02;
const D76: f64 = -0.15418974869023643374053993627e+03;
const D77: f64 = -0.23152937917604549567536039109e+03;
const D78: f64 = 0.35763911791061412378285349910e+03;
const D79: f64 = 0.93405324183624310003907691704e+02;
const D710: f64 = -0.37458323136451633156875139351e+02;
const D711: f64 = 0.10409964950896230045147246184e+03;
const D712: f64 = 0.29840293426660503123344363579e+02;
const D713: f64 = -0.43533456590011143754432175058e+02;
const D714: f64 = 0.96324553959188282948394950600e+02;
const D715: f64 = -0.39177261675615439165231486172e+02;
const D716: f64 = -0.14972683625798562581422125276e+03;

/// Stage storage and dense-output coefficients of DOP853.
///
/// `k[j]` holds stage `j + 1` of the step (`k[0]` = `f(t, y)`), `k[12]` is
/// `f(t + h, y_new)` and `k[13..16]` the three extra dense-output stages.
#[derive(Clone)]
pub(crate) struct Dop853<const N: usize> {
    k: [[f64; N]; 16],
    y_new: [f64; N],
    /// `CONT` of `dop853.f` (see [`Dense`] impl for the evaluation formula).
    cont: [[f64; N]; 8],
}

impl<const N: usize> Dop853<N> {
    pub(crate) fn new() -> Self {
        Self {
            k: [[0.0; N]; 16],
            y_new: [0.0; N],
            cont: [[0.0; N]; 8],
        }
    }

    /// `y1 = y + h * sum_j coef_j * k[stage_j]` (stages 1-based as in the
    /// Fortran code), followed by `k[out] = f(t + c h, y1)`.
    #[allow(clippy::too_many_arguments)]
    fn stage<S: OdeSystem<N>, const M: usize>(
        &mut self,
        sys: &mut S,
        stats: &mut Stats,
        t: f64,
        y: &[f64; N],
        h: f64,
        c: f64,
        terms: [(f64, usize); M],
        out: usize,
    ) {
        let mut y1 = [0.0; N];
        for i in 0..N {
            let mut s = 0.0;
            for &(a, j) in &terms {
                s += a * self.k[j - 1][i];
            }
            y1[i] = y[i] + h * s;
        }
        rhs(sys, stats, t + c * h, &y1, &mut self.k[out - 1]);
    }
}

impl<const N: usize> Dense<N> for Dop853<N> {
    /// `CONTD8`: with `s1 = 1 - s`,
    /// `conpar = c4 + s(c5 + s1(c6 + s c7))` and
    /// `u(s) = c0 + s(c1 + s1(c2 + s(c3 + s1 conpar)))`.
    fn eval(&self, s: f64, out: &mut [f64; N]) {
        let s1 = 1.0 - s;
        let c = &self.cont;
        for i in 0..N {
            let conpar = c[4][i] + s * (c[5][i] + s1 * (c[6][i] + s * c[7][i]));
            out[i] = c[0][i] + s * (c[1][i] + s1 * (c[2][i] + s * (c[3][i] + s1 * conpar)));
        }
    }

    fn eval_dtheta(&self, s: f64, out: &mut [f64; N]) {
        let s1 = 1.0 - s;
        let c = &self.cont;
        for i in 0..N {
            let a = c[6][i] + s * c[7][i];
            let da = c[7][i];
            let b = c[5][i] + s1 * a;
            let db = -a + s1 * da;
            let p = c[4][i] + s * b;
            let dp = b + s * db;
            let q = c[3][i] + s1 * p;
            let dq = -p + s1 * dp;
            let r = c[2][i] + s * q;
            let dr = q + s * dq;
            let u = c[1][i] + s1 * r;
            let du = -r + s1 * dr;
            out[i] = u + s * du;
        }
    }
}

impl<const N: usize> Stepper<N> for Dop853<N> {
    const HINIT_ORDER: i32 = 8;
    const CONTROL: ControlKind = ControlKind::Lund {
        base: 1.0 / 8.0,
        weight: 0.2,
    };

    fn start<S: OdeSystem<N>>(&mut self, sys: &mut S, t: f64, y: &[f64; N], stats: &mut Stats) {
        rhs(sys, stats, t, y, &mut self.k[0]);
    }

    fn f0(&self) -> &[f64; N] {
        &self.k[0]
    }

    fn attempt<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        tol: &Tolerances,
        stats: &mut Stats,
    ) -> f64 {
        let st = stats;
        self.stage(sys, st, t, y, h, C2, [(A21, 1)], 2);
        self.stage(sys, st, t, y, h, C3, [(A31, 1), (A32, 2)], 3);
        self.stage(sys, st, t, y, h, C4, [(A41, 1), (A43, 3)], 4);
        self.stage(sys, st, t, y, h, C5, [(A51, 1), (A53, 3), (A54, 4)], 5);
        self.stage(sys, st, t, y, h, C6, [(A61, 1), (A64, 4), (A65, 5)], 6);
        let a7 = [(A71, 1), (A74, 4), (A75, 5), (A76, 6)];
        self.stage(sys, st, t, y, h, C7, a7, 7);
        let a8 = [(A81, 1), (A84, 4), (A85, 5), (A86, 6), (A87, 7)];
        self.stage(sys, st, t, y, h, C8, a8, 8);
        let a9 = [(A91, 1), (A94, 4), (A95, 5), (A96, 6), (A97, 7), (A98, 8)];
        self.stage(sys, st, t, y, h, C9, a9, 9);
        let a10 = [
            (A101, 1),
            (A104, 4),
            (A105, 5),
            (A106, 6),
            (A107, 7),
            (A108, 8),
            (A109, 9),
        ];
        self.stage(sys, st, t, y, h, C10, a10, 10);
        let a11 = [
            (A111, 1),
            (A114, 4),
            (A115, 5),
            (A116, 6),
            (A117, 7),
            (A118, 8),
            (A119, 9),
            (A1110, 10),
        ];
        self.stage(sys, st, t, y, h, C11, a11, 11);
        let a12 = [
            (A121, 1),
            (A124, 4),
            (A125, 5),
            (A126, 6),
            (A127, 7),
            (A128, 8),
            (A129, 9),
            (A1210, 10),
            (A1211, 11),
        ];
        self.stage(sys, st, t, y, h, 1.0, a12, 12);

        let k = &self.k;
        let mut incr = [0.0; N];
        for i in 0..N {
            incr[i] = B1 * k[0][i]
                + B6 * k[5][i]
                + B7 * k[6][i]
                + B8 * k[7][i]
                + B9 * k[8][i]
                + B10 * k[9][i]
                + B11 * k[10][i]
                + B12 * k[11][i];
            self.y_new[i] = y[i] + h * incr[i];
        }
        let n = sys.controlled_components(t, y, t + h, &self.y_new).min(N);
        let mut err = 0.0;
        let mut err2 = 0.0;
        for i in 0..n {
            let incr = incr[i];
            let sk = tol.atol + tol.rtol * y[i].abs().max(self.y_new[i].abs());
            // 3rd-order embedded estimate.
            let e3 = incr - BHH1 * k[0][i] - BHH2 * k[8][i] - BHH3 * k[11][i];
            err2 += (e3 / sk).powi(2);
            // 5th-order embedded estimate.
            let e5 = ER1 * k[0][i]
                + ER6 * k[5][i]
                + ER7 * k[6][i]
                + ER8 * k[7][i]
                + ER9 * k[8][i]
                + ER10 * k[9][i]
                + ER11 * k[10][i]
                + ER12 * k[11][i];
            err += (e5 / sk).powi(2);
        }
        if n == 0 {
            return 0.0;
        }
        let mut deno = err + 0.01 * err2;
        if deno <= 0.0 {
            deno = 1.0;
        }
        h.abs() * err * (1.0 / (n as f64 * deno)).sqrt()
    }

    fn y_new(&self) -> &[f64; N] {
        &self.y_new
    }

    fn accept<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        dense: bool,
        stats: &mut Stats,
    ) {
        let y_new = self.y_new;
        rhs(sys, stats, t + h, &y_new, &mut self.k[12]);
        if dense {
            let k = &self.k;
            for i in 0..N {
                let ydiff = y_new[i] - y[i];
                let bspl = h * k[0][i] - ydiff;
                self.cont[0][i] = y[i];
                self.cont[1][i] = ydiff;
                self.cont[2][i] = bspl;
                self.cont[3][i] = ydiff - h * k[12][i] - bspl;
            }
            let st = stats;
            let a14 = [
                (A141, 1),
                (A147, 7),
                (A148, 8),
                (A149, 9),
                (A1410, 10),
                (A1411, 11),
                (A1412, 12),
                (A1413, 13),
            ];
            self.stage(sys, st, t, y, h, C14, a14, 14);
            let a15 = [
                (A151, 1),
                (A156, 6),
                (A157, 7),
                (A158, 8),
                (A1511, 11),
                (A1512, 12),
                (A1513, 13),
                (A1514, 14),
            ];
            self.stage(sys, st, t, y, h, C15, a15, 15);
            let a16 = [
                (A161, 1),
                (A166, 6),
                (A167, 7),
                (A168, 8),
                (A169, 9),
                (A1613, 13),
                (A1614, 14),
                (A1615, 15),
            ];
            self.stage(sys, st, t, y, h, C16, a16, 16);
            // Rows 4..7 of CONT: weights for stages 1, 6..16.
            const D: [[f64; 12]; 4] = [
                [
                    D41, D46, D47, D48, D49, D410, D411, D412, D413, D414, D415, D416,
                ],
                [
                    D51, D56, D57, D58, D59, D510, D511, D512, D513, D514, D515, D516,
                ],
                [
                    D61, D66, D67, D68, D69, D610, D611, D612, D613, D614, D615, D616,
                ],
                [
                    D71, D76, D77, D78, D79, D710, D711, D712, D713, D714, D715, D716,
                ],
            ];
            const STAGES: [usize; 12] = [1, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16];
            let k = &self.k;
            for (row, d) in D.iter().enumerate() {
                for i in 0..N {
                    let mut s = 0.0;
                    for (dj, &j) in d.iter().zip(STAGES.iter()) {
                        s += dj * k[j - 1][i];
                    }
                    self.cont[4 + row][i] = h * s;
                }
            }
        }
        // First same as last.
        self.k[0] = self.k[12];
    }
}
