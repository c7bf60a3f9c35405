/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for constrained_dynamics() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: cfb213c907b133d8468816b35e2514e88b652abe0e80fc54ab4677cd1d4b1854
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_constrained_dynamics_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_fmax CASADI_PREFIX(fmax)
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

casadi_real casadi_fmax(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x>y ? x : y;
#else
  return fmax(x, y);
#endif
}

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na1_constrained_dynamics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {16, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {3, 3, 1};

/* snakecg_na1_constrained_dynamics:(q[4],v[4],tau,q_obj[3],v_obj[3],f_obj[3],K[16],contact_link[2],side,object_mass,object_inertia,rho[2],wheel_offset[2],free[3],lam_fixed[3],regularization)->(qdd[4],a_obj[3],lam[3],w[3],gap,s,norm_lambda,norm_a_obj,norm_qdd,sr,pivot_ratio,delassus[3x3],b[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79;
  a00=arg[1]? arg[1][3] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a02=(a00+a01);
  a02=casadi_sq(a02);
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a03=sin(a03);
  a05=sin(a05);
  a08=(a03*a05);
  a07=(a07-a08);
  a08=arg[6]? arg[6][7] : 0;
  a09=(a07*a08);
  a10=(a02*a09);
  a11=casadi_sq(a01);
  a12=arg[6]? arg[6][2] : 0;
  a13=arg[6]? arg[6][6] : 0;
  a12=(a12-a13);
  a14=(a04*a12);
  a15=(a11*a14);
  a10=(a10+a15);
  a15=arg[6]? arg[6][1] : 0;
  a10=(a10*a15);
  a16=arg[6]? arg[6][8] : 0;
  a17=(a10/a16);
  a18=arg[6]? arg[6][10] : 0;
  a05=(a04*a05);
  a19=(a06*a03);
  a19=(a05+a19);
  a20=(a18*a19);
  a21=arg[6]? arg[6][9] : 0;
  a22=(a21*a03);
  a22=(a20+a22);
  a23=(a22/a16);
  a24=(a23*a10);
  a25=(a19*a08);
  a26=(a12*a03);
  a27=arg[0]? arg[0][1] : 0;
  a28=(a26+a27);
  a29=(a25+a28);
  a29=(a10*a29);
  a30=(a02*a25);
  a31=(a11*a26);
  a30=(a30+a31);
  a31=arg[0]? arg[0][0] : 0;
  a32=(a14+a31);
  a33=(a09+a32);
  a33=(a30*a33);
  a33=(a33*a15);
  a29=(a29-a33);
  a33=(a10*a27);
  a33=(a29-a33);
  a30=(a30*a15);
  a15=(a30*a31);
  a33=(a33+a15);
  a24=(a24-a33);
  a18=(a18*a07);
  a21=(a21*a04);
  a21=(a18+a21);
  a33=(a21/a16);
  a15=(a33*a30);
  a24=(a24-a15);
  a15=(a07*a04);
  a34=(a19*a03);
  a15=(a15+a34);
  a34=arg[6]? arg[6][12] : 0;
  a15=(a15*a34);
  a34=arg[6]? arg[6][14] : 0;
  a34=(a15+a34);
  a35=arg[6]? arg[6][15] : 0;
  a15=(a15+a35);
  a34=(a34+a15);
  a36=casadi_sq(a23);
  a36=(a36*a16);
  a36=(a34-a36);
  a37=casadi_sq(a33);
  a37=(a37*a16);
  a36=(a36-a37);
  a37=(a24/a36);
  a38=(a20/a16);
  a39=(a38*a23);
  a39=(a39*a16);
  a39=(a15-a39);
  a40=(a18/a16);
  a41=(a40*a33);
  a41=(a41*a16);
  a39=(a39-a41);
  a39=(a39/a36);
  a41=arg[2]? arg[2][0] : 0;
  a28=(a10*a28);
  a29=(a29-a28);
  a32=(a30*a32);
  a29=(a29+a32);
  a41=(a41-a29);
  a10=(a38*a10);
  a41=(a41+a10);
  a10=(a40*a30);
  a41=(a41-a10);
  a24=(a39*a24);
  a41=(a41-a24);
  a24=casadi_sq(a38);
  a24=(a24*a16);
  a24=(a35-a24);
  a10=casadi_sq(a40);
  a10=(a10*a16);
  a24=(a24-a10);
  a10=casadi_sq(a39);
  a10=(a10*a36);
  a24=(a24-a10);
  a41=(a41/a24);
  a10=(a39*a41);
  a37=(a37-a10);
  a10=(a23*a37);
  a17=(a17+a10);
  a10=(a38*a41);
  a17=(a17+a10);
  a10=arg[7]? arg[7][0] : 0;
  a29=(a10*a03);
  a32=arg[7]? arg[7][1] : 0;
  a06=(a03*a06);
  a06=(a06+a05);
  a05=(a32*a06);
  a29=(a29+a05);
  a05=arg[8]? arg[8][0] : 0;
  a28=(a29*a05);
  a42=(a10+a32);
  a43=(a28*a42);
  a44=(a43/a16);
  a26=(a27+a26);
  a26=(a26+a25);
  a45=(a27-a26);
  a46=(a32*a45);
  a47=(a28*a46);
  a48=(a10*a04);
  a49=(a32*a07);
  a48=(a48+a49);
  a49=(a48*a05);
  a14=(a31+a14);
  a14=(a14+a09);
  a50=(a14-a31);
  a51=(a32*a50);
  a52=(a49*a51);
  a47=(a47-a52);
  a13=(a13*a10);
  a52=(a08*a32);
  a13=(a13+a52);
  a52=(a05*a13);
  a53=casadi_sq(a29);
  a53=(a52*a53);
  a54=casadi_sq(a48);
  a52=(a52*a54);
  a53=(a53+a52);
  a52=arg[3]? arg[3][2] : 0;
  a54=cos(a52);
  a55=arg[11]? arg[11][1] : 0;
  a56=(a54*a55);
  a52=sin(a52);
  a57=arg[11]? arg[11][0] : 0;
  a58=(a52*a57);
  a56=(a56+a58);
  a58=arg[3]? arg[3][1] : 0;
  a58=(a56+a58);
  a59=(a29*a13);
  a58=(a58+a59);
  a27=(a27*a10);
  a26=(a26*a32);
  a27=(a27+a26);
  a58=(a58-a27);
  a27=(a28*a58);
  a53=(a53-a27);
  a54=(a54*a57);
  a52=(a52*a55);
  a54=(a54-a52);
  a52=arg[3]? arg[3][0] : 0;
  a52=(a54+a52);
  a13=(a48*a13);
  a52=(a52+a13);
  a31=(a31*a10);
  a14=(a14*a32);
  a31=(a31+a14);
  a52=(a52-a31);
  a31=(a49*a52);
  a53=(a53-a31);
  a31=(a53*a42);
  a47=(a47+a31);
  a31=(a23*a43);
  a31=(a47+a31);
  a14=(a49*a42);
  a10=(a33*a14);
  a31=(a31+a10);
  a10=(a31/a36);
  a53=(a53*a32);
  a13=(a32*a25);
  a55=(a28*a13);
  a57=(a32*a09);
  a27=(a49*a57);
  a55=(a55+a27);
  a53=(a53-a55);
  a55=(a38*a43);
  a55=(a53+a55);
  a27=(a40*a14);
  a55=(a55+a27);
  a31=(a39*a31);
  a55=(a55-a31);
  a55=(a55/a24);
  a31=(a39*a55);
  a10=(a10-a31);
  a31=(a23*a10);
  a44=(a44+a31);
  a31=(a38*a55);
  a44=(a44+a31);
  a31=1.;
  a27=arg[13]? arg[13][0] : 0;
  a26=(a31-a27);
  a59=arg[14]? arg[14][0] : 0;
  a59=(a26*a59);
  a60=(a43*a17);
  a30=(a30/a16);
  a61=(a33*a37);
  a30=(a30-a61);
  a61=(a40*a41);
  a30=(a30-a61);
  a61=(a14*a30);
  a60=(a60-a61);
  a61=(a47*a37);
  a60=(a60+a61);
  a61=(a53*a41);
  a60=(a60+a61);
  a61=arg[5]? arg[5][1] : 0;
  a62=arg[9]? arg[9][0] : 0;
  a61=(a61/a62);
  a63=(a49*a61);
  a64=arg[5]? arg[5][0] : 0;
  a64=(a64/a62);
  a65=(a28*a64);
  a63=(a63-a65);
  a65=(a48*a54);
  a65=(a65*a05);
  a66=(a28*a56);
  a65=(a65+a66);
  a66=arg[5]? arg[5][2] : 0;
  a67=arg[10]? arg[10][0] : 0;
  a66=(a66/a67);
  a68=(a65*a66);
  a63=(a63+a68);
  a60=(a60+a63);
  a63=arg[1]? arg[1][0] : 0;
  a68=(a42*a63);
  a46=(a46*a01);
  a68=(a68+a46);
  a13=(a13*a00);
  a68=(a68-a13);
  a68=(a49*a68);
  a13=(a42*a01);
  a46=(a32*a00);
  a13=(a13+a46);
  a46=(a68*a13);
  a08=(a08*a02);
  a02=(a07*a08);
  a11=(a11*a12);
  a12=(a04*a11);
  a02=(a02+a12);
  a12=(a02*a32);
  a12=(a28*a12);
  a46=(a46-a12);
  a12=arg[1]? arg[1][1] : 0;
  a42=(a42*a12);
  a51=(a51*a01);
  a42=(a42+a51);
  a57=(a57*a00);
  a42=(a42+a57);
  a42=(a28*a42);
  a57=(a42*a13);
  a46=(a46+a57);
  a68=(a68+a42);
  a56=(a56*a49);
  a54=(a28*a54);
  a42=(a56-a54);
  a57=arg[4]? arg[4][2] : 0;
  a51=(a42*a57);
  a68=(a68+a51);
  a51=arg[4]? arg[4][0] : 0;
  a51=(a49*a51);
  a68=(a68-a51);
  a69=arg[4]? arg[4][1] : 0;
  a69=(a28*a69);
  a68=(a68-a69);
  a70=(a58*a49);
  a71=(a29*a52);
  a71=(a71*a05);
  a70=(a70-a71);
  a71=(a70*a13);
  a68=(a68-a71);
  a68=(a13*a68);
  a46=(a46+a68);
  a42=(a42*a13);
  a54=(a54-a56);
  a54=(a57*a54);
  a42=(a42+a54);
  a57=(a57*a42);
  a46=(a46+a57);
  a51=(a51*a13);
  a46=(a46-a51);
  a69=(a69*a13);
  a46=(a46-a69);
  a08=(a08*a19);
  a11=(a11*a03);
  a08=(a08+a11);
  a32=(a08*a32);
  a32=(a49*a32);
  a46=(a46+a32);
  a60=(a60+a46);
  a46=(a43*a44);
  a32=(a14/a16);
  a11=(a33*a10);
  a32=(a32+a11);
  a11=(a40*a55);
  a32=(a32+a11);
  a11=(a14*a32);
  a46=(a46+a11);
  a11=(a47*a10);
  a46=(a46+a11);
  a11=(a53*a55);
  a46=(a46+a11);
  a11=(a28/a62);
  a28=(a28*a11);
  a19=(a49/a62);
  a49=(a49*a19);
  a28=(a28+a49);
  a49=(a65/a67);
  a65=(a65*a49);
  a28=(a28+a65);
  a46=(a46+a28);
  a28=(a46*a59);
  a65=arg[12]? arg[12][0] : 0;
  a69=(a23*a03);
  a69=(a65-a69);
  a13=(a33*a04);
  a69=(a69-a13);
  a13=(a69/a36);
  a51=(a38*a03);
  a57=(a40*a04);
  a51=(a51+a57);
  a69=(a39*a69);
  a51=(a51+a69);
  a51=(a51/a24);
  a69=(a39*a51);
  a13=(a13+a69);
  a69=(a23*a13);
  a57=(a03/a16);
  a69=(a69-a57);
  a57=(a38*a51);
  a69=(a69-a57);
  a57=(a43*a69);
  a42=(a04/a16);
  a54=(a33*a13);
  a42=(a42-a54);
  a54=(a40*a51);
  a42=(a42+a54);
  a54=(a14*a42);
  a57=(a57-a54);
  a54=(a47*a13);
  a57=(a57+a54);
  a54=(a53*a51);
  a57=(a57-a54);
  a54=arg[13]? arg[13][1] : 0;
  a56=(a31-a54);
  a68=arg[14]? arg[14][1] : 0;
  a68=(a56*a68);
  a71=(a57*a68);
  a28=(a28+a71);
  a71=(a07*a50);
  a05=(a06*a45);
  a71=(a71-a05);
  a05=arg[12]? arg[12][1] : 0;
  a71=(a71+a05);
  a72=(a23*a06);
  a72=(a71-a72);
  a73=(a33*a07);
  a72=(a72-a73);
  a36=(a72/a36);
  a73=(a06*a25);
  a74=(a07*a09);
  a73=(a73+a74);
  a73=(a73+a05);
  a05=(a38*a06);
  a05=(a73-a05);
  a74=(a40*a07);
  a05=(a05-a74);
  a72=(a39*a72);
  a05=(a05-a72);
  a05=(a05/a24);
  a39=(a39*a05);
  a36=(a36-a39);
  a23=(a23*a36);
  a39=(a06/a16);
  a23=(a23-a39);
  a38=(a38*a05);
  a23=(a23+a38);
  a43=(a43*a23);
  a38=(a07/a16);
  a33=(a33*a36);
  a38=(a38-a33);
  a40=(a40*a05);
  a38=(a38-a40);
  a14=(a14*a38);
  a43=(a43-a14);
  a47=(a47*a36);
  a43=(a43+a47);
  a53=(a53*a05);
  a43=(a43+a53);
  a53=arg[13]? arg[13][2] : 0;
  a47=(a31-a53);
  a14=arg[14]? arg[14][2] : 0;
  a14=(a47*a14);
  a40=(a43*a14);
  a28=(a28+a40);
  a28=(a60+a28);
  a28=(a27*a28);
  a40=(a27*a46);
  a40=(a40*a27);
  a40=(a40+a26);
  a26=arg[15]? arg[15][0] : 0;
  a33=(a26*a27);
  a40=(a40+a33);
  a33=(a28/a40);
  a39=(a65*a10);
  a24=(a03*a44);
  a72=(a04*a32);
  a24=(a24+a72);
  a39=(a39-a24);
  a24=(a54*a39);
  a24=(a24*a27);
  a24=(a24/a40);
  a72=(a24*a28);
  a74=(a04*a30);
  a75=(a03*a17);
  a74=(a74-a75);
  a75=(a65*a37);
  a74=(a74+a75);
  a75=(a03*a12);
  a75=(a75*a01);
  a76=(a04*a63);
  a76=(a76*a01);
  a75=(a75+a76);
  a74=(a74-a75);
  a75=(a39*a59);
  a76=(a04*a42);
  a77=(a03*a69);
  a76=(a76-a77);
  a77=(a65*a13);
  a76=(a76+a77);
  a77=(a76*a68);
  a75=(a75+a77);
  a04=(a04*a38);
  a03=(a03*a23);
  a04=(a04-a03);
  a65=(a65*a36);
  a04=(a04+a65);
  a65=(a04*a14);
  a75=(a75+a65);
  a75=(a74+a75);
  a75=(a54*a75);
  a72=(a72-a75);
  a75=(a54*a76);
  a75=(a75*a54);
  a75=(a75+a56);
  a56=(a26*a54);
  a75=(a75+a56);
  a56=casadi_sq(a24);
  a56=(a56*a40);
  a56=(a75-a56);
  a65=(a72/a56);
  a03=(a07*a42);
  a77=(a06*a69);
  a03=(a03-a77);
  a77=(a71*a13);
  a03=(a03+a77);
  a77=(a73*a51);
  a03=(a03-a77);
  a77=(a53*a03);
  a77=(a77*a54);
  a54=(a71*a10);
  a78=(a06*a44);
  a79=(a07*a32);
  a78=(a78+a79);
  a54=(a54-a78);
  a78=(a73*a55);
  a54=(a54+a78);
  a78=(a53*a54);
  a78=(a78*a27);
  a78=(a78/a40);
  a27=(a78*a24);
  a27=(a27*a40);
  a77=(a77-a27);
  a77=(a77/a56);
  a28=(a78*a28);
  a27=(a07*a30);
  a79=(a06*a17);
  a27=(a27-a79);
  a79=(a71*a37);
  a27=(a27+a79);
  a79=(a73*a41);
  a27=(a27+a79);
  a02=(a06*a02);
  a08=(a07*a08);
  a02=(a02-a08);
  a50=(a50*a01);
  a12=(a12+a50);
  a09=(a09*a00);
  a12=(a12+a09);
  a12=(a06*a12);
  a09=(a01+a00);
  a12=(a12*a09);
  a02=(a02-a12);
  a45=(a45*a01);
  a63=(a63+a45);
  a25=(a25*a00);
  a63=(a63-a25);
  a63=(a07*a63);
  a63=(a63*a09);
  a02=(a02-a63);
  a27=(a27+a02);
  a02=(a54*a59);
  a63=(a03*a68);
  a02=(a02+a63);
  a07=(a07*a38);
  a06=(a06*a23);
  a07=(a07-a06);
  a71=(a71*a36);
  a07=(a07+a71);
  a73=(a73*a05);
  a07=(a07+a73);
  a73=(a07*a14);
  a02=(a02+a73);
  a02=(a27+a02);
  a02=(a53*a02);
  a28=(a28-a02);
  a72=(a77*a72);
  a28=(a28-a72);
  a72=(a53*a07);
  a72=(a72*a53);
  a72=(a72+a47);
  a26=(a26*a53);
  a72=(a72+a26);
  a26=casadi_sq(a78);
  a26=(a26*a40);
  a26=(a72-a26);
  a40=casadi_sq(a77);
  a40=(a40*a56);
  a26=(a26-a40);
  a28=(a28/a26);
  a77=(a77*a28);
  a65=(a65-a77);
  a24=(a24*a65);
  a33=(a33+a24);
  a78=(a78*a28);
  a33=(a33+a78);
  a59=(a59-a33);
  a44=(a44*a59);
  a65=(a65+a68);
  a69=(a69*a65);
  a44=(a44+a69);
  a28=(a28+a14);
  a23=(a23*a28);
  a44=(a44+a23);
  a17=(a17+a44);
  if (res[0]!=0) res[0][0]=a17;
  a42=(a42*a65);
  a32=(a32*a59);
  a42=(a42-a32);
  a38=(a38*a28);
  a42=(a42+a38);
  a30=(a30+a42);
  if (res[0]!=0) res[0][1]=a30;
  a10=(a10*a59);
  a13=(a13*a65);
  a10=(a10+a13);
  a36=(a36*a28);
  a10=(a10+a36);
  a37=(a37+a10);
  if (res[0]!=0) res[0][2]=a37;
  a55=(a55*a59);
  a51=(a51*a65);
  a55=(a55-a51);
  a05=(a05*a28);
  a55=(a55+a05);
  a41=(a41+a55);
  if (res[0]!=0) res[0][3]=a41;
  a11=(a11*a59);
  a64=(a64-a11);
  if (res[1]!=0) res[1][0]=a64;
  a19=(a19*a59);
  a61=(a61+a19);
  if (res[1]!=0) res[1][1]=a61;
  a49=(a49*a59);
  a66=(a66+a49);
  if (res[1]!=0) res[1][2]=a66;
  if (res[2]!=0) res[2][0]=a59;
  if (res[2]!=0) res[2][1]=a65;
  if (res[2]!=0) res[2][2]=a28;
  a49=(a46*a59);
  a19=(a57*a65);
  a49=(a49+a19);
  a19=(a43*a28);
  a49=(a49+a19);
  a49=(a49+a60);
  if (res[3]!=0) res[3][0]=a49;
  a49=(a39*a59);
  a19=(a76*a65);
  a49=(a49+a19);
  a19=(a04*a28);
  a49=(a49+a19);
  a49=(a49+a74);
  if (res[3]!=0) res[3][1]=a49;
  a49=(a54*a59);
  a19=(a03*a65);
  a49=(a49+a19);
  a19=(a07*a28);
  a49=(a49+a19);
  a49=(a49+a27);
  if (res[3]!=0) res[3][2]=a49;
  if (res[4]!=0) res[4][0]=a70;
  a29=(a29*a58);
  a48=(a48*a52);
  a29=(a29+a48);
  if (res[5]!=0) res[5][0]=a29;
  a29=(a59*a46);
  a48=(a65*a39);
  a29=(a29+a48);
  a48=(a28*a54);
  a29=(a29+a48);
  a29=(a29*a59);
  a48=(a59*a57);
  a52=(a65*a76);
  a48=(a48+a52);
  a52=(a28*a03);
  a48=(a48+a52);
  a48=(a48*a65);
  a29=(a29+a48);
  a59=(a59*a43);
  a65=(a65*a04);
  a59=(a59+a65);
  a65=(a28*a07);
  a59=(a59+a65);
  a59=(a59*a28);
  a29=(a29+a59);
  if (res[6]!=0) res[6][0]=a29;
  a29=(a62*a64);
  a64=(a64*a29);
  a62=(a62*a61);
  a61=(a61*a62);
  a64=(a64+a61);
  a67=(a67*a66);
  a66=(a66*a67);
  a64=(a64+a66);
  if (res[7]!=0) res[7][0]=a64;
  a66=(a17*a16);
  a67=(a37*a22);
  a66=(a66-a67);
  a67=(a41*a20);
  a66=(a66-a67);
  a66=(a66*a17);
  a16=(a30*a16);
  a67=(a37*a21);
  a16=(a16+a67);
  a67=(a41*a18);
  a16=(a16+a67);
  a16=(a16*a30);
  a66=(a66+a16);
  a21=(a30*a21);
  a22=(a17*a22);
  a21=(a21-a22);
  a34=(a37*a34);
  a21=(a21+a34);
  a34=(a41*a15);
  a21=(a21+a34);
  a21=(a21*a37);
  a66=(a66+a21);
  a30=(a30*a18);
  a17=(a17*a20);
  a30=(a30-a17);
  a37=(a37*a15);
  a30=(a30+a37);
  a35=(a41*a35);
  a30=(a30+a35);
  a30=(a30*a41);
  a66=(a66+a30);
  if (res[8]!=0) res[8][0]=a66;
  a66=(a64+a66);
  a30=1.0000000000000000e-300;
  a66=casadi_fmax(a66,a30);
  a64=(a64/a66);
  if (res[9]!=0) res[9][0]=a64;
  a56=(a56/a75);
  a31=casadi_fmin(a31,a56);
  a26=(a26/a72);
  a31=casadi_fmin(a31,a26);
  if (res[10]!=0) res[10][0]=a31;
  if (res[11]!=0) res[11][0]=a46;
  if (res[11]!=0) res[11][1]=a39;
  if (res[11]!=0) res[11][2]=a54;
  if (res[11]!=0) res[11][3]=a57;
  if (res[11]!=0) res[11][4]=a76;
  if (res[11]!=0) res[11][5]=a03;
  if (res[11]!=0) res[11][6]=a43;
  if (res[11]!=0) res[11][7]=a04;
  if (res[11]!=0) res[11][8]=a07;
  if (res[12]!=0) res[12][0]=a60;
  if (res[12]!=0) res[12][1]=a74;
  if (res[12]!=0) res[12][2]=a27;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_constrained_dynamics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_constrained_dynamics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_constrained_dynamics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_constrained_dynamics_n_in(void) { return 16;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_constrained_dynamics_n_out(void) { return 13;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_constrained_dynamics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_constrained_dynamics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "tau";
    case 3: return "q_obj";
    case 4: return "v_obj";
    case 5: return "f_obj";
    case 6: return "K";
    case 7: return "contact_link";
    case 8: return "side";
    case 9: return "object_mass";
    case 10: return "object_inertia";
    case 11: return "rho";
    case 12: return "wheel_offset";
    case 13: return "free";
    case 14: return "lam_fixed";
    case 15: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_constrained_dynamics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "qdd";
    case 1: return "a_obj";
    case 2: return "lam";
    case 3: return "w";
    case 4: return "gap";
    case 5: return "s";
    case 6: return "norm_lambda";
    case 7: return "norm_a_obj";
    case 8: return "norm_qdd";
    case 9: return "sr";
    case 10: return "pivot_ratio";
    case 11: return "delassus";
    case 12: return "b";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_constrained_dynamics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    case 4: return casadi_s2;
    case 5: return casadi_s2;
    case 6: return casadi_s3;
    case 7: return casadi_s4;
    case 8: return casadi_s1;
    case 9: return casadi_s1;
    case 10: return casadi_s1;
    case 11: return casadi_s4;
    case 12: return casadi_s4;
    case 13: return casadi_s2;
    case 14: return casadi_s2;
    case 15: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_constrained_dynamics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    case 4: return casadi_s1;
    case 5: return casadi_s1;
    case 6: return casadi_s1;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    case 9: return casadi_s1;
    case 10: return casadi_s1;
    case 11: return casadi_s5;
    case 12: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16;
  if (sz_res) *sz_res = 13;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_constrained_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 13*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_constrained_dynamics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[16];
  casadi_real* r[13];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 81);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 16; ++k) a[k] = 0;
  for (k = 0; k < 13; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    a[8] = arg[8] + i * stride[8];
    a[9] = arg[9] + i * stride[9];
    a[10] = arg[10] + i * stride[10];
    a[11] = arg[11] + i * stride[11];
    a[12] = arg[12] + i * stride[12];
    a[13] = arg[13] + i * stride[13];
    a[14] = arg[14] + i * stride[14];
    a[15] = arg[15] + i * stride[15];
    r[0] = res[0] + i * 4;
    r[1] = res[1] + i * 3;
    r[2] = res[2] + i * 3;
    r[3] = res[3] + i * 3;
    r[4] = res[4] + i * 1;
    r[5] = res[5] + i * 1;
    r[6] = res[6] + i * 1;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    r[9] = res[9] + i * 1;
    r[10] = res[10] + i * 1;
    r[11] = res[11] + i * 9;
    r[12] = res[12] + i * 3;
    if (snakecg_na1_constrained_dynamics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
