/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for constrained_dynamics() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 69ac8a580508aa26bce28f4a88e0f77c0b28e33b1f2694eb6cf4bbbcae64a5df
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
  a00=arg[1]? arg[1][2] : 0;
  a01=casadi_sq(a00);
  a02=arg[0]? arg[0][2] : 0;
  a03=cos(a02);
  a04=arg[6]? arg[6][2] : 0;
  a05=arg[6]? arg[6][6] : 0;
  a04=(a04-a05);
  a06=(a03*a04);
  a07=(a01*a06);
  a08=arg[1]? arg[1][3] : 0;
  a09=(a08+a00);
  a09=casadi_sq(a09);
  a10=arg[0]? arg[0][3] : 0;
  a10=(a10+a02);
  a11=cos(a10);
  a12=arg[6]? arg[6][7] : 0;
  a13=(a11*a12);
  a14=(a09*a13);
  a07=(a07+a14);
  a14=arg[6]? arg[6][1] : 0;
  a07=(a07*a14);
  a15=arg[6]? arg[6][8] : 0;
  a16=(a07/a15);
  a17=arg[6]? arg[6][10] : 0;
  a18=sin(a10);
  a19=(a17*a18);
  a20=arg[6]? arg[6][9] : 0;
  a21=sin(a02);
  a22=(a20*a21);
  a22=(a19+a22);
  a23=(a22/a15);
  a24=(a23*a07);
  a25=(a18*a12);
  a26=(a04*a21);
  a27=arg[0]? arg[0][1] : 0;
  a28=(a26+a27);
  a29=(a25+a28);
  a29=(a07*a29);
  a30=(a01*a26);
  a31=(a09*a25);
  a30=(a30+a31);
  a31=arg[0]? arg[0][0] : 0;
  a32=(a06+a31);
  a33=(a13+a32);
  a33=(a30*a33);
  a33=(a33*a14);
  a29=(a29-a33);
  a33=(a07*a27);
  a33=(a29-a33);
  a30=(a30*a14);
  a14=(a30*a31);
  a33=(a33+a14);
  a24=(a24-a33);
  a17=(a17*a11);
  a20=(a20*a03);
  a20=(a17+a20);
  a33=(a20/a15);
  a14=(a33*a30);
  a24=(a24-a14);
  a14=(a03*a11);
  a34=(a21*a18);
  a14=(a14+a34);
  a34=arg[6]? arg[6][12] : 0;
  a14=(a14*a34);
  a34=arg[6]? arg[6][14] : 0;
  a34=(a14+a34);
  a35=arg[6]? arg[6][15] : 0;
  a14=(a14+a35);
  a34=(a34+a14);
  a36=casadi_sq(a23);
  a36=(a36*a15);
  a36=(a34-a36);
  a37=casadi_sq(a33);
  a37=(a37*a15);
  a36=(a36-a37);
  a37=(a24/a36);
  a38=(a19/a15);
  a39=(a38*a23);
  a39=(a39*a15);
  a39=(a14-a39);
  a40=(a17/a15);
  a41=(a40*a33);
  a41=(a41*a15);
  a39=(a39-a41);
  a39=(a39/a36);
  a41=arg[2]? arg[2][0] : 0;
  a28=(a07*a28);
  a29=(a29-a28);
  a32=(a30*a32);
  a29=(a29+a32);
  a41=(a41-a29);
  a07=(a38*a07);
  a41=(a41+a07);
  a07=(a40*a30);
  a41=(a41-a07);
  a24=(a39*a24);
  a41=(a41-a24);
  a24=casadi_sq(a38);
  a24=(a24*a15);
  a24=(a35-a24);
  a07=casadi_sq(a40);
  a07=(a07*a15);
  a24=(a24-a07);
  a07=casadi_sq(a39);
  a07=(a07*a36);
  a24=(a24-a07);
  a41=(a41/a24);
  a07=(a39*a41);
  a37=(a37-a07);
  a07=(a23*a37);
  a16=(a16+a07);
  a07=(a38*a41);
  a16=(a16+a07);
  a07=arg[7]? arg[7][0] : 0;
  a02=(a02*a07);
  a29=arg[7]? arg[7][1] : 0;
  a10=(a10*a29);
  a02=(a02+a10);
  a10=sin(a02);
  a32=arg[8]? arg[8][0] : 0;
  a28=(a10*a32);
  a42=(a07+a29);
  a43=(a28*a42);
  a44=(a43/a15);
  a26=(a27+a26);
  a26=(a26+a25);
  a45=(a27-a26);
  a46=(a29*a45);
  a47=(a28*a46);
  a02=cos(a02);
  a48=(a02*a32);
  a06=(a31+a06);
  a06=(a06+a13);
  a49=(a06-a31);
  a50=(a29*a49);
  a51=(a48*a50);
  a47=(a47-a51);
  a05=(a05*a07);
  a51=(a12*a29);
  a05=(a05+a51);
  a51=(a32*a05);
  a52=arg[3]? arg[3][2] : 0;
  a53=cos(a52);
  a54=arg[11]? arg[11][1] : 0;
  a55=(a53*a54);
  a52=sin(a52);
  a56=arg[11]? arg[11][0] : 0;
  a57=(a52*a56);
  a55=(a55+a57);
  a57=arg[3]? arg[3][1] : 0;
  a57=(a55+a57);
  a58=(a10*a05);
  a57=(a57+a58);
  a27=(a27*a07);
  a26=(a26*a29);
  a27=(a27+a26);
  a57=(a57-a27);
  a27=(a28*a57);
  a51=(a51-a27);
  a53=(a53*a56);
  a52=(a52*a54);
  a53=(a53-a52);
  a52=arg[3]? arg[3][0] : 0;
  a52=(a53+a52);
  a05=(a02*a05);
  a52=(a52+a05);
  a31=(a31*a07);
  a06=(a06*a29);
  a31=(a31+a06);
  a52=(a52-a31);
  a31=(a48*a52);
  a51=(a51-a31);
  a31=(a51*a42);
  a47=(a47+a31);
  a31=(a23*a43);
  a31=(a47+a31);
  a06=(a48*a42);
  a07=(a33*a06);
  a31=(a31+a07);
  a07=(a31/a36);
  a51=(a51*a29);
  a05=(a29*a25);
  a54=(a28*a05);
  a56=(a29*a13);
  a27=(a48*a56);
  a54=(a54+a27);
  a51=(a51-a54);
  a54=(a38*a43);
  a54=(a51+a54);
  a27=(a40*a06);
  a54=(a54+a27);
  a31=(a39*a31);
  a54=(a54-a31);
  a54=(a54/a24);
  a31=(a39*a54);
  a07=(a07-a31);
  a31=(a23*a07);
  a44=(a44+a31);
  a31=(a38*a54);
  a44=(a44+a31);
  a31=1.;
  a27=arg[13]? arg[13][0] : 0;
  a26=(a31-a27);
  a58=arg[14]? arg[14][0] : 0;
  a58=(a26*a58);
  a59=(a43*a16);
  a30=(a30/a15);
  a60=(a33*a37);
  a30=(a30-a60);
  a60=(a40*a41);
  a30=(a30-a60);
  a60=(a06*a30);
  a59=(a59-a60);
  a60=(a47*a37);
  a59=(a59+a60);
  a60=(a51*a41);
  a59=(a59+a60);
  a60=arg[5]? arg[5][1] : 0;
  a61=arg[9]? arg[9][0] : 0;
  a60=(a60/a61);
  a62=(a48*a60);
  a63=arg[5]? arg[5][0] : 0;
  a63=(a63/a61);
  a64=(a28*a63);
  a62=(a62-a64);
  a64=(a02*a53);
  a64=(a64*a32);
  a65=(a28*a55);
  a64=(a64+a65);
  a65=arg[5]? arg[5][2] : 0;
  a66=arg[10]? arg[10][0] : 0;
  a65=(a65/a66);
  a67=(a64*a65);
  a62=(a62+a67);
  a59=(a59+a62);
  a62=arg[1]? arg[1][0] : 0;
  a67=(a42*a62);
  a46=(a46*a00);
  a67=(a67+a46);
  a05=(a05*a08);
  a67=(a67-a05);
  a67=(a48*a67);
  a05=(a42*a00);
  a46=(a29*a08);
  a05=(a05+a46);
  a46=(a67*a05);
  a01=(a01*a04);
  a04=(a03*a01);
  a12=(a12*a09);
  a09=(a11*a12);
  a04=(a04+a09);
  a09=(a04*a29);
  a09=(a28*a09);
  a46=(a46-a09);
  a09=arg[1]? arg[1][1] : 0;
  a42=(a42*a09);
  a50=(a50*a00);
  a42=(a42+a50);
  a56=(a56*a08);
  a42=(a42+a56);
  a42=(a28*a42);
  a56=(a42*a05);
  a46=(a46+a56);
  a67=(a67+a42);
  a55=(a55*a48);
  a53=(a28*a53);
  a42=(a55-a53);
  a56=arg[4]? arg[4][2] : 0;
  a50=(a42*a56);
  a67=(a67+a50);
  a50=arg[4]? arg[4][0] : 0;
  a50=(a48*a50);
  a67=(a67-a50);
  a68=arg[4]? arg[4][1] : 0;
  a68=(a28*a68);
  a67=(a67-a68);
  a69=(a57*a48);
  a70=(a10*a52);
  a70=(a70*a32);
  a69=(a69-a70);
  a70=(a69*a05);
  a67=(a67-a70);
  a67=(a05*a67);
  a46=(a46+a67);
  a42=(a42*a05);
  a53=(a53-a55);
  a53=(a56*a53);
  a42=(a42+a53);
  a56=(a56*a42);
  a46=(a46+a56);
  a50=(a50*a05);
  a46=(a46-a50);
  a68=(a68*a05);
  a46=(a46-a68);
  a01=(a01*a21);
  a12=(a12*a18);
  a01=(a01+a12);
  a29=(a01*a29);
  a29=(a48*a29);
  a46=(a46+a29);
  a59=(a59+a46);
  a46=(a43*a44);
  a29=(a06/a15);
  a12=(a33*a07);
  a29=(a29+a12);
  a12=(a40*a54);
  a29=(a29+a12);
  a12=(a06*a29);
  a46=(a46+a12);
  a12=(a47*a07);
  a46=(a46+a12);
  a12=(a51*a54);
  a46=(a46+a12);
  a12=(a28/a61);
  a28=(a28*a12);
  a68=(a48/a61);
  a48=(a48*a68);
  a28=(a28+a48);
  a48=(a64/a66);
  a64=(a64*a48);
  a28=(a28+a64);
  a46=(a46+a28);
  a28=(a46*a58);
  a64=arg[12]? arg[12][0] : 0;
  a05=(a23*a21);
  a05=(a64-a05);
  a50=(a33*a03);
  a05=(a05-a50);
  a50=(a05/a36);
  a56=(a38*a21);
  a42=(a40*a03);
  a56=(a56+a42);
  a05=(a39*a05);
  a56=(a56+a05);
  a56=(a56/a24);
  a05=(a39*a56);
  a50=(a50+a05);
  a05=(a23*a50);
  a42=(a21/a15);
  a05=(a05-a42);
  a42=(a38*a56);
  a05=(a05-a42);
  a42=(a43*a05);
  a53=(a03/a15);
  a55=(a33*a50);
  a53=(a53-a55);
  a55=(a40*a56);
  a53=(a53+a55);
  a55=(a06*a53);
  a42=(a42-a55);
  a55=(a47*a50);
  a42=(a42+a55);
  a55=(a51*a56);
  a42=(a42-a55);
  a55=arg[13]? arg[13][1] : 0;
  a67=(a31-a55);
  a70=arg[14]? arg[14][1] : 0;
  a70=(a67*a70);
  a32=(a42*a70);
  a28=(a28+a32);
  a32=(a11*a49);
  a71=(a18*a45);
  a32=(a32-a71);
  a71=arg[12]? arg[12][1] : 0;
  a32=(a32+a71);
  a72=(a23*a18);
  a72=(a32-a72);
  a73=(a33*a11);
  a72=(a72-a73);
  a36=(a72/a36);
  a73=(a18*a25);
  a74=(a11*a13);
  a73=(a73+a74);
  a73=(a73+a71);
  a71=(a38*a18);
  a71=(a73-a71);
  a74=(a40*a11);
  a71=(a71-a74);
  a72=(a39*a72);
  a71=(a71-a72);
  a71=(a71/a24);
  a39=(a39*a71);
  a36=(a36-a39);
  a23=(a23*a36);
  a39=(a18/a15);
  a23=(a23-a39);
  a38=(a38*a71);
  a23=(a23+a38);
  a43=(a43*a23);
  a38=(a11/a15);
  a33=(a33*a36);
  a38=(a38-a33);
  a40=(a40*a71);
  a38=(a38-a40);
  a06=(a06*a38);
  a43=(a43-a06);
  a47=(a47*a36);
  a43=(a43+a47);
  a51=(a51*a71);
  a43=(a43+a51);
  a51=arg[13]? arg[13][2] : 0;
  a47=(a31-a51);
  a06=arg[14]? arg[14][2] : 0;
  a06=(a47*a06);
  a40=(a43*a06);
  a28=(a28+a40);
  a28=(a59+a28);
  a28=(a27*a28);
  a40=(a27*a46);
  a40=(a40*a27);
  a40=(a40+a26);
  a26=arg[15]? arg[15][0] : 0;
  a33=(a26*a27);
  a40=(a40+a33);
  a33=(a28/a40);
  a39=(a64*a07);
  a24=(a21*a44);
  a72=(a03*a29);
  a24=(a24+a72);
  a39=(a39-a24);
  a24=(a55*a39);
  a24=(a24*a27);
  a24=(a24/a40);
  a72=(a24*a28);
  a74=(a03*a30);
  a75=(a21*a16);
  a74=(a74-a75);
  a75=(a64*a37);
  a74=(a74+a75);
  a75=(a21*a09);
  a75=(a75*a00);
  a76=(a03*a62);
  a76=(a76*a00);
  a75=(a75+a76);
  a74=(a74-a75);
  a75=(a39*a58);
  a76=(a03*a53);
  a77=(a21*a05);
  a76=(a76-a77);
  a77=(a64*a50);
  a76=(a76+a77);
  a77=(a76*a70);
  a75=(a75+a77);
  a03=(a03*a38);
  a21=(a21*a23);
  a03=(a03-a21);
  a64=(a64*a36);
  a03=(a03+a64);
  a64=(a03*a06);
  a75=(a75+a64);
  a75=(a74+a75);
  a75=(a55*a75);
  a72=(a72-a75);
  a75=(a55*a76);
  a75=(a75*a55);
  a75=(a75+a67);
  a67=(a26*a55);
  a75=(a75+a67);
  a67=casadi_sq(a24);
  a67=(a67*a40);
  a67=(a75-a67);
  a64=(a72/a67);
  a21=(a11*a53);
  a77=(a18*a05);
  a21=(a21-a77);
  a77=(a32*a50);
  a21=(a21+a77);
  a77=(a73*a56);
  a21=(a21-a77);
  a77=(a51*a21);
  a77=(a77*a55);
  a55=(a32*a07);
  a78=(a18*a44);
  a79=(a11*a29);
  a78=(a78+a79);
  a55=(a55-a78);
  a78=(a73*a54);
  a55=(a55+a78);
  a78=(a51*a55);
  a78=(a78*a27);
  a78=(a78/a40);
  a27=(a78*a24);
  a27=(a27*a40);
  a77=(a77-a27);
  a77=(a77/a67);
  a28=(a78*a28);
  a27=(a11*a30);
  a79=(a18*a16);
  a27=(a27-a79);
  a79=(a32*a37);
  a27=(a27+a79);
  a79=(a73*a41);
  a27=(a27+a79);
  a04=(a18*a04);
  a01=(a11*a01);
  a04=(a04-a01);
  a49=(a49*a00);
  a09=(a09+a49);
  a13=(a13*a08);
  a09=(a09+a13);
  a09=(a18*a09);
  a13=(a00+a08);
  a09=(a09*a13);
  a04=(a04-a09);
  a45=(a45*a00);
  a62=(a62+a45);
  a25=(a25*a08);
  a62=(a62-a25);
  a62=(a11*a62);
  a62=(a62*a13);
  a04=(a04-a62);
  a27=(a27+a04);
  a04=(a55*a58);
  a62=(a21*a70);
  a04=(a04+a62);
  a11=(a11*a38);
  a18=(a18*a23);
  a11=(a11-a18);
  a32=(a32*a36);
  a11=(a11+a32);
  a73=(a73*a71);
  a11=(a11+a73);
  a73=(a11*a06);
  a04=(a04+a73);
  a04=(a27+a04);
  a04=(a51*a04);
  a28=(a28-a04);
  a72=(a77*a72);
  a28=(a28-a72);
  a72=(a51*a11);
  a72=(a72*a51);
  a72=(a72+a47);
  a26=(a26*a51);
  a72=(a72+a26);
  a26=casadi_sq(a78);
  a26=(a26*a40);
  a26=(a72-a26);
  a40=casadi_sq(a77);
  a40=(a40*a67);
  a26=(a26-a40);
  a28=(a28/a26);
  a77=(a77*a28);
  a64=(a64-a77);
  a24=(a24*a64);
  a33=(a33+a24);
  a78=(a78*a28);
  a33=(a33+a78);
  a58=(a58-a33);
  a44=(a44*a58);
  a64=(a64+a70);
  a05=(a05*a64);
  a44=(a44+a05);
  a28=(a28+a06);
  a23=(a23*a28);
  a44=(a44+a23);
  a16=(a16+a44);
  if (res[0]!=0) res[0][0]=a16;
  a53=(a53*a64);
  a29=(a29*a58);
  a53=(a53-a29);
  a38=(a38*a28);
  a53=(a53+a38);
  a30=(a30+a53);
  if (res[0]!=0) res[0][1]=a30;
  a07=(a07*a58);
  a50=(a50*a64);
  a07=(a07+a50);
  a36=(a36*a28);
  a07=(a07+a36);
  a37=(a37+a07);
  if (res[0]!=0) res[0][2]=a37;
  a54=(a54*a58);
  a56=(a56*a64);
  a54=(a54-a56);
  a71=(a71*a28);
  a54=(a54+a71);
  a41=(a41+a54);
  if (res[0]!=0) res[0][3]=a41;
  a12=(a12*a58);
  a63=(a63-a12);
  if (res[1]!=0) res[1][0]=a63;
  a68=(a68*a58);
  a60=(a60+a68);
  if (res[1]!=0) res[1][1]=a60;
  a48=(a48*a58);
  a65=(a65+a48);
  if (res[1]!=0) res[1][2]=a65;
  if (res[2]!=0) res[2][0]=a58;
  if (res[2]!=0) res[2][1]=a64;
  if (res[2]!=0) res[2][2]=a28;
  a48=(a46*a58);
  a68=(a42*a64);
  a48=(a48+a68);
  a68=(a43*a28);
  a48=(a48+a68);
  a48=(a48+a59);
  if (res[3]!=0) res[3][0]=a48;
  a48=(a39*a58);
  a68=(a76*a64);
  a48=(a48+a68);
  a68=(a03*a28);
  a48=(a48+a68);
  a48=(a48+a74);
  if (res[3]!=0) res[3][1]=a48;
  a48=(a55*a58);
  a68=(a21*a64);
  a48=(a48+a68);
  a68=(a11*a28);
  a48=(a48+a68);
  a48=(a48+a27);
  if (res[3]!=0) res[3][2]=a48;
  if (res[4]!=0) res[4][0]=a69;
  a10=(a10*a57);
  a02=(a02*a52);
  a10=(a10+a02);
  if (res[5]!=0) res[5][0]=a10;
  a10=(a58*a46);
  a02=(a64*a39);
  a10=(a10+a02);
  a02=(a28*a55);
  a10=(a10+a02);
  a10=(a10*a58);
  a02=(a58*a42);
  a52=(a64*a76);
  a02=(a02+a52);
  a52=(a28*a21);
  a02=(a02+a52);
  a02=(a02*a64);
  a10=(a10+a02);
  a58=(a58*a43);
  a64=(a64*a03);
  a58=(a58+a64);
  a64=(a28*a11);
  a58=(a58+a64);
  a58=(a58*a28);
  a10=(a10+a58);
  if (res[6]!=0) res[6][0]=a10;
  a10=(a61*a63);
  a63=(a63*a10);
  a61=(a61*a60);
  a60=(a60*a61);
  a63=(a63+a60);
  a66=(a66*a65);
  a65=(a65*a66);
  a63=(a63+a65);
  if (res[7]!=0) res[7][0]=a63;
  a65=(a16*a15);
  a66=(a37*a22);
  a65=(a65-a66);
  a66=(a41*a19);
  a65=(a65-a66);
  a65=(a65*a16);
  a15=(a30*a15);
  a66=(a37*a20);
  a15=(a15+a66);
  a66=(a41*a17);
  a15=(a15+a66);
  a15=(a15*a30);
  a65=(a65+a15);
  a20=(a30*a20);
  a22=(a16*a22);
  a20=(a20-a22);
  a34=(a37*a34);
  a20=(a20+a34);
  a34=(a41*a14);
  a20=(a20+a34);
  a20=(a20*a37);
  a65=(a65+a20);
  a30=(a30*a17);
  a16=(a16*a19);
  a30=(a30-a16);
  a37=(a37*a14);
  a30=(a30+a37);
  a35=(a41*a35);
  a30=(a30+a35);
  a30=(a30*a41);
  a65=(a65+a30);
  if (res[8]!=0) res[8][0]=a65;
  a65=(a63+a65);
  a30=1.0000000000000000e-300;
  a65=casadi_fmax(a65,a30);
  a63=(a63/a65);
  if (res[9]!=0) res[9][0]=a63;
  a67=(a67/a75);
  a31=casadi_fmin(a31,a67);
  a26=(a26/a72);
  a31=casadi_fmin(a31,a26);
  if (res[10]!=0) res[10][0]=a31;
  if (res[11]!=0) res[11][0]=a46;
  if (res[11]!=0) res[11][1]=a39;
  if (res[11]!=0) res[11][2]=a55;
  if (res[11]!=0) res[11][3]=a42;
  if (res[11]!=0) res[11][4]=a76;
  if (res[11]!=0) res[11][5]=a21;
  if (res[11]!=0) res[11][6]=a43;
  if (res[11]!=0) res[11][7]=a03;
  if (res[11]!=0) res[11][8]=a11;
  if (res[12]!=0) res[12][0]=a59;
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
