/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_extremes() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: cf8b78e4ac8543d3c9937e833ddcc109ad8d455bb5995199ae5dfb19801e274c
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_metric_extremes_ ## ID
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

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na1_metric_extremes_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};
static const casadi_int casadi_s5[3] = {1, 2, 1};

/* snakecg_na1_metric_extremes:(q[4],K[16],contact_link[2],side,object_mass,object_inertia,q_obj[3],rho[2],wheel_offset[2],free[3],free_lost[3],regularization)->(norm_a_obj_kept[2],tau_norm_a_obj_kept[1x2],norm_qdd_kept[2],tau_norm_qdd_kept[1x2],norm_lambda_kept[2],tau_norm_lambda_kept[1x2],norm_a_obj_lost[2],tau_norm_a_obj_lost[1x2],norm_qdd_lost[2],tau_norm_qdd_lost[1x2],norm_lambda_lost[2],tau_norm_lambda_lost[1x2],sr_kept[2],tau_sr_kept[1x2],contact_from_tau,pivot_ratio_kept,pivot_ratio_lost) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65;
  a00=arg[0]? arg[0][2] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][3] : 0;
  a04=(a03+a00);
  a05=arg[2]? arg[2][1] : 0;
  a06=(a04*a05);
  a02=(a02+a06);
  a06=sin(a02);
  a07=arg[3]? arg[3][0] : 0;
  a08=(a06*a07);
  a09=arg[4]? arg[4][0] : 0;
  a10=(a08/a09);
  a11=arg[9]? arg[9][0] : 0;
  a12=(a01+a05);
  a13=(a08*a12);
  a14=arg[1]? arg[1][10] : 0;
  a15=cos(a00);
  a16=sin(a03);
  a17=(a15*a16);
  a03=cos(a03);
  a00=sin(a00);
  a18=(a03*a00);
  a17=(a17+a18);
  a18=(a14*a17);
  a19=arg[1]? arg[1][8] : 0;
  a20=(a18/a19);
  a21=arg[1]? arg[1][15] : 0;
  a22=casadi_sq(a20);
  a22=(a22*a19);
  a22=(a21-a22);
  a03=(a15*a03);
  a16=(a00*a16);
  a03=(a03-a16);
  a14=(a14*a03);
  a16=(a14/a19);
  a23=casadi_sq(a16);
  a23=(a23*a19);
  a22=(a22-a23);
  a23=(a03*a15);
  a24=(a17*a00);
  a23=(a23+a24);
  a24=arg[1]? arg[1][12] : 0;
  a23=(a23*a24);
  a24=(a23+a21);
  a25=arg[1]? arg[1][9] : 0;
  a26=(a25*a00);
  a26=(a18+a26);
  a27=(a26/a19);
  a28=(a20*a27);
  a28=(a28*a19);
  a28=(a24-a28);
  a25=(a25*a15);
  a25=(a14+a25);
  a29=(a25/a19);
  a30=(a16*a29);
  a30=(a30*a19);
  a28=(a28-a30);
  a30=arg[1]? arg[1][14] : 0;
  a23=(a23+a30);
  a23=(a23+a24);
  a30=casadi_sq(a27);
  a30=(a30*a19);
  a30=(a23-a30);
  a31=casadi_sq(a29);
  a31=(a31*a19);
  a30=(a30-a31);
  a28=(a28/a30);
  a31=casadi_sq(a28);
  a31=(a31*a30);
  a22=(a22-a31);
  a31=(a20/a22);
  a32=(a28/a22);
  a33=(a27*a32);
  a31=(a31-a33);
  a33=(a13*a31);
  a02=cos(a02);
  a34=(a02*a07);
  a35=(a34*a12);
  a36=(a29*a32);
  a37=(a16/a22);
  a36=(a36-a37);
  a37=(a35*a36);
  a33=(a33-a37);
  a37=arg[0]? arg[0][1] : 0;
  a38=arg[1]? arg[1][2] : 0;
  a39=arg[1]? arg[1][6] : 0;
  a38=(a38-a39);
  a40=(a38*a00);
  a40=(a37+a40);
  a41=arg[1]? arg[1][7] : 0;
  a17=(a17*a41);
  a40=(a40+a17);
  a42=(a37-a40);
  a43=(a05*a42);
  a43=(a08*a43);
  a44=arg[0]? arg[0][0] : 0;
  a38=(a15*a38);
  a38=(a44+a38);
  a03=(a03*a41);
  a38=(a38+a03);
  a45=(a38-a44);
  a46=(a05*a45);
  a46=(a34*a46);
  a43=(a43-a46);
  a39=(a39*a01);
  a41=(a41*a05);
  a39=(a39+a41);
  a41=(a07*a39);
  a46=arg[6]? arg[6][2] : 0;
  a47=cos(a46);
  a48=arg[7]? arg[7][1] : 0;
  a49=(a47*a48);
  a46=sin(a46);
  a50=arg[7]? arg[7][0] : 0;
  a51=(a46*a50);
  a49=(a49+a51);
  a51=arg[6]? arg[6][1] : 0;
  a51=(a49+a51);
  a06=(a06*a39);
  a51=(a51+a06);
  a37=(a37*a01);
  a40=(a40*a05);
  a37=(a37+a40);
  a51=(a51-a37);
  a51=(a08*a51);
  a41=(a41-a51);
  a47=(a47*a50);
  a46=(a46*a48);
  a47=(a47-a46);
  a46=arg[6]? arg[6][0] : 0;
  a46=(a47+a46);
  a39=(a02*a39);
  a46=(a46+a39);
  a44=(a44*a01);
  a38=(a38*a05);
  a44=(a44+a38);
  a46=(a46-a44);
  a46=(a34*a46);
  a41=(a41-a46);
  a12=(a41*a12);
  a43=(a43+a12);
  a12=(a43*a32);
  a33=(a33-a12);
  a41=(a41*a05);
  a12=(a05*a17);
  a12=(a08*a12);
  a05=(a05*a03);
  a05=(a34*a05);
  a12=(a12+a05);
  a41=(a41-a12);
  a12=(a41/a22);
  a33=(a33+a12);
  a12=(a11*a33);
  a05=(a13/a19);
  a46=(a27*a13);
  a46=(a43+a46);
  a44=(a29*a35);
  a46=(a46+a44);
  a44=(a46/a30);
  a38=(a20*a13);
  a38=(a41+a38);
  a01=(a16*a35);
  a38=(a38+a01);
  a46=(a28*a46);
  a38=(a38-a46);
  a38=(a38/a22);
  a46=(a28*a38);
  a44=(a44-a46);
  a46=(a27*a44);
  a05=(a05+a46);
  a46=(a20*a38);
  a05=(a05+a46);
  a46=(a13*a05);
  a01=(a35/a19);
  a39=(a29*a44);
  a01=(a01+a39);
  a39=(a16*a38);
  a01=(a01+a39);
  a39=(a35*a01);
  a46=(a46+a39);
  a39=(a43*a44);
  a46=(a46+a39);
  a39=(a41*a38);
  a46=(a46+a39);
  a39=(a08*a10);
  a48=(a34/a09);
  a34=(a34*a48);
  a39=(a39+a34);
  a02=(a02*a47);
  a02=(a02*a07);
  a08=(a08*a49);
  a02=(a02+a08);
  a08=arg[5]? arg[5][0] : 0;
  a49=(a02/a08);
  a02=(a02*a49);
  a39=(a39+a02);
  a46=(a46+a39);
  a39=(a11*a46);
  a39=(a39*a11);
  a02=1.;
  a07=(a02-a11);
  a39=(a39+a07);
  a07=arg[11]? arg[11][0] : 0;
  a47=(a07*a11);
  a39=(a39+a47);
  a47=(a12/a39);
  a34=arg[9]? arg[9][1] : 0;
  a50=arg[8]? arg[8][0] : 0;
  a51=(a50*a44);
  a37=(a00*a05);
  a40=(a15*a01);
  a37=(a37+a40);
  a51=(a51-a37);
  a37=(a34*a51);
  a37=(a37*a11);
  a37=(a37/a39);
  a40=(a15*a36);
  a06=(a00*a31);
  a40=(a40-a06);
  a06=(a50*a32);
  a40=(a40-a06);
  a06=(a34*a40);
  a52=(a37*a12);
  a06=(a06-a52);
  a52=(a15/a19);
  a53=(a27*a00);
  a53=(a50-a53);
  a54=(a29*a15);
  a53=(a53-a54);
  a54=(a53/a30);
  a55=(a20*a00);
  a56=(a16*a15);
  a55=(a55+a56);
  a53=(a28*a53);
  a55=(a55+a53);
  a55=(a55/a22);
  a53=(a28*a55);
  a54=(a54+a53);
  a53=(a29*a54);
  a52=(a52-a53);
  a53=(a16*a55);
  a52=(a52+a53);
  a53=(a15*a52);
  a56=(a27*a54);
  a57=(a00/a19);
  a56=(a56-a57);
  a57=(a20*a55);
  a56=(a56-a57);
  a57=(a00*a56);
  a53=(a53-a57);
  a57=(a50*a54);
  a53=(a53+a57);
  a57=(a34*a53);
  a57=(a57*a34);
  a58=(a02-a34);
  a57=(a57+a58);
  a58=(a07*a34);
  a57=(a57+a58);
  a58=casadi_sq(a37);
  a58=(a58*a39);
  a58=(a57-a58);
  a59=(a06/a58);
  a60=arg[9]? arg[9][2] : 0;
  a61=cos(a04);
  a62=(a61*a52);
  a04=sin(a04);
  a63=(a04*a56);
  a62=(a62-a63);
  a45=(a61*a45);
  a42=(a04*a42);
  a45=(a45-a42);
  a42=arg[8]? arg[8][1] : 0;
  a45=(a45+a42);
  a63=(a45*a54);
  a62=(a62+a63);
  a17=(a04*a17);
  a03=(a61*a03);
  a17=(a17+a03);
  a17=(a17+a42);
  a42=(a17*a55);
  a62=(a62-a42);
  a42=(a60*a62);
  a42=(a42*a34);
  a34=(a45*a44);
  a03=(a04*a05);
  a63=(a61*a01);
  a03=(a03+a63);
  a34=(a34-a03);
  a03=(a17*a38);
  a34=(a34+a03);
  a03=(a60*a34);
  a03=(a03*a11);
  a03=(a03/a39);
  a11=(a03*a37);
  a11=(a11*a39);
  a42=(a42-a11);
  a42=(a42/a58);
  a11=(a61*a36);
  a63=(a04*a31);
  a11=(a11-a63);
  a63=(a45*a32);
  a11=(a11-a63);
  a63=(a17/a22);
  a11=(a11+a63);
  a63=(a60*a11);
  a12=(a03*a12);
  a63=(a63-a12);
  a06=(a42*a06);
  a63=(a63-a06);
  a06=(a61/a19);
  a12=(a27*a04);
  a12=(a45-a12);
  a64=(a29*a61);
  a12=(a12-a64);
  a30=(a12/a30);
  a64=(a20*a04);
  a64=(a17-a64);
  a65=(a16*a61);
  a64=(a64-a65);
  a12=(a28*a12);
  a64=(a64-a12);
  a64=(a64/a22);
  a28=(a28*a64);
  a30=(a30-a28);
  a29=(a29*a30);
  a06=(a06-a29);
  a16=(a16*a64);
  a06=(a06-a16);
  a61=(a61*a06);
  a27=(a27*a30);
  a16=(a04/a19);
  a27=(a27-a16);
  a20=(a20*a64);
  a27=(a27+a20);
  a04=(a04*a27);
  a61=(a61-a04);
  a45=(a45*a30);
  a61=(a61+a45);
  a17=(a17*a64);
  a61=(a61+a17);
  a17=(a60*a61);
  a17=(a17*a60);
  a45=(a02-a60);
  a17=(a17+a45);
  a60=(a07*a60);
  a17=(a17+a60);
  a60=casadi_sq(a03);
  a60=(a60*a39);
  a60=(a17-a60);
  a39=casadi_sq(a42);
  a39=(a39*a58);
  a60=(a60-a39);
  a63=(a63/a60);
  a42=(a42*a63);
  a59=(a59-a42);
  a37=(a37*a59);
  a47=(a47-a37);
  a03=(a03*a63);
  a47=(a47-a03);
  a03=(a10*a47);
  a37=(a03*a09);
  a37=(a37*a03);
  a03=(a48*a47);
  a42=(a03*a09);
  a42=(a42*a03);
  a37=(a37+a42);
  a42=(a49*a47);
  a03=(a42*a08);
  a03=(a03*a42);
  a37=(a37+a03);
  a03=(1./a22);
  a42=sqrt(a03);
  a39=(a37/a42);
  a39=(a39/a42);
  if (res[0]!=0) res[0][0]=a39;
  if (res[0]!=0) res[0][1]=a39;
  a45=(1./a42);
  if (res[1]!=0) res[1][0]=a45;
  if (res[1]!=0) res[1][1]=a45;
  a04=(a05*a47);
  a20=(a56*a59);
  a04=(a04+a20);
  a20=(a27*a63);
  a04=(a04+a20);
  a04=(a31-a04);
  a20=(a04*a19);
  a16=(a44*a47);
  a29=(a54*a59);
  a16=(a16+a29);
  a29=(a30*a63);
  a16=(a16+a29);
  a16=(a32+a16);
  a29=(a16*a26);
  a20=(a20+a29);
  a29=(a55*a59);
  a28=(a38*a47);
  a29=(a29-a28);
  a28=(a64*a63);
  a29=(a29-a28);
  a29=(a03+a29);
  a28=(a29*a18);
  a20=(a20-a28);
  a20=(a20*a04);
  a28=(a01*a47);
  a12=(a52*a59);
  a28=(a28-a12);
  a12=(a06*a63);
  a28=(a28-a12);
  a28=(a36+a28);
  a12=(a28*a19);
  a65=(a16*a25);
  a12=(a12-a65);
  a65=(a29*a14);
  a12=(a12+a65);
  a12=(a12*a28);
  a20=(a20+a12);
  a12=(a28*a25);
  a65=(a04*a26);
  a12=(a12-a65);
  a65=(a16*a23);
  a12=(a12-a65);
  a65=(a29*a24);
  a12=(a12+a65);
  a12=(a12*a16);
  a20=(a20-a12);
  a28=(a28*a14);
  a04=(a04*a18);
  a28=(a28-a04);
  a16=(a16*a24);
  a28=(a28-a16);
  a16=(a29*a21);
  a28=(a28+a16);
  a28=(a28*a29);
  a20=(a20+a28);
  a28=(a20/a42);
  a28=(a28/a42);
  if (res[2]!=0) res[2][0]=a28;
  if (res[2]!=0) res[2][1]=a28;
  if (res[3]!=0) res[3][0]=a45;
  if (res[3]!=0) res[3][1]=a45;
  a28=(a47*a46);
  a29=(a59*a51);
  a28=(a28+a29);
  a29=(a63*a34);
  a28=(a28+a29);
  a28=(a28*a47);
  a29=(a13*a56);
  a16=(a35*a52);
  a29=(a29-a16);
  a16=(a43*a54);
  a29=(a29+a16);
  a16=(a41*a55);
  a29=(a29-a16);
  a16=(a47*a29);
  a04=(a59*a53);
  a16=(a16+a04);
  a04=(a63*a62);
  a16=(a16+a04);
  a16=(a16*a59);
  a28=(a28+a16);
  a13=(a13*a27);
  a35=(a35*a06);
  a13=(a13-a35);
  a43=(a43*a30);
  a13=(a13+a43);
  a41=(a41*a64);
  a13=(a13+a41);
  a41=(a47*a13);
  a15=(a15*a06);
  a00=(a00*a27);
  a15=(a15-a00);
  a50=(a50*a30);
  a15=(a15+a50);
  a59=(a59*a15);
  a41=(a41+a59);
  a59=(a63*a61);
  a41=(a41+a59);
  a41=(a41*a63);
  a28=(a28+a41);
  a28=(a28/a42);
  a28=(a28/a42);
  if (res[4]!=0) res[4][0]=a28;
  if (res[4]!=0) res[4][1]=a28;
  if (res[5]!=0) res[5][0]=a45;
  if (res[5]!=0) res[5][1]=a45;
  a28=arg[10]? arg[10][0] : 0;
  a33=(a28*a33);
  a41=(a28*a46);
  a41=(a41*a28);
  a63=(a02-a28);
  a41=(a41+a63);
  a63=(a07*a28);
  a41=(a41+a63);
  a63=(a33/a41);
  a59=arg[10]? arg[10][1] : 0;
  a50=(a59*a51);
  a50=(a50*a28);
  a50=(a50/a41);
  a40=(a59*a40);
  a00=(a50*a33);
  a40=(a40-a00);
  a00=(a59*a53);
  a00=(a00*a59);
  a43=(a02-a59);
  a00=(a00+a43);
  a43=(a07*a59);
  a00=(a00+a43);
  a43=casadi_sq(a50);
  a43=(a43*a41);
  a43=(a00-a43);
  a35=(a40/a43);
  a16=arg[10]? arg[10][2] : 0;
  a04=(a16*a62);
  a04=(a04*a59);
  a59=(a16*a34);
  a59=(a59*a28);
  a59=(a59/a41);
  a28=(a59*a50);
  a28=(a28*a41);
  a04=(a04-a28);
  a04=(a04/a43);
  a11=(a16*a11);
  a33=(a59*a33);
  a11=(a11-a33);
  a40=(a04*a40);
  a11=(a11-a40);
  a40=(a16*a61);
  a40=(a40*a16);
  a33=(a02-a16);
  a40=(a40+a33);
  a07=(a07*a16);
  a40=(a40+a07);
  a07=casadi_sq(a59);
  a07=(a07*a41);
  a07=(a40-a07);
  a41=casadi_sq(a04);
  a41=(a41*a43);
  a07=(a07-a41);
  a11=(a11/a07);
  a04=(a04*a11);
  a35=(a35-a04);
  a50=(a50*a35);
  a63=(a63-a50);
  a59=(a59*a11);
  a63=(a63-a59);
  a10=(a10*a63);
  a59=(a10*a09);
  a59=(a59*a10);
  a48=(a48*a63);
  a09=(a48*a09);
  a09=(a09*a48);
  a59=(a59+a09);
  a49=(a49*a63);
  a08=(a49*a08);
  a08=(a08*a49);
  a59=(a59+a08);
  a59=(a59/a42);
  a59=(a59/a42);
  if (res[6]!=0) res[6][0]=a59;
  if (res[6]!=0) res[6][1]=a59;
  if (res[7]!=0) res[7][0]=a45;
  if (res[7]!=0) res[7][1]=a45;
  a05=(a05*a63);
  a56=(a56*a35);
  a05=(a05+a56);
  a27=(a27*a11);
  a05=(a05+a27);
  a31=(a31-a05);
  a05=(a31*a19);
  a44=(a44*a63);
  a54=(a54*a35);
  a44=(a44+a54);
  a30=(a30*a11);
  a44=(a44+a30);
  a32=(a32+a44);
  a44=(a32*a26);
  a05=(a05+a44);
  a55=(a55*a35);
  a38=(a38*a63);
  a55=(a55-a38);
  a64=(a64*a11);
  a55=(a55-a64);
  a03=(a03+a55);
  a55=(a03*a18);
  a05=(a05-a55);
  a05=(a05*a31);
  a01=(a01*a63);
  a52=(a52*a35);
  a01=(a01-a52);
  a06=(a06*a11);
  a01=(a01-a06);
  a36=(a36+a01);
  a19=(a36*a19);
  a01=(a32*a25);
  a19=(a19-a01);
  a01=(a03*a14);
  a19=(a19+a01);
  a19=(a19*a36);
  a05=(a05+a19);
  a25=(a36*a25);
  a26=(a31*a26);
  a25=(a25-a26);
  a23=(a32*a23);
  a25=(a25-a23);
  a23=(a03*a24);
  a25=(a25+a23);
  a25=(a25*a32);
  a05=(a05-a25);
  a36=(a36*a14);
  a31=(a31*a18);
  a36=(a36-a31);
  a32=(a32*a24);
  a36=(a36-a32);
  a21=(a03*a21);
  a36=(a36+a21);
  a36=(a36*a03);
  a05=(a05+a36);
  a05=(a05/a42);
  a05=(a05/a42);
  if (res[8]!=0) res[8][0]=a05;
  if (res[8]!=0) res[8][1]=a05;
  if (res[9]!=0) res[9][0]=a45;
  if (res[9]!=0) res[9][1]=a45;
  a46=(a63*a46);
  a51=(a35*a51);
  a46=(a46+a51);
  a34=(a11*a34);
  a46=(a46+a34);
  a46=(a46*a63);
  a29=(a63*a29);
  a53=(a35*a53);
  a29=(a29+a53);
  a62=(a11*a62);
  a29=(a29+a62);
  a29=(a29*a35);
  a46=(a46+a29);
  a63=(a63*a13);
  a35=(a35*a15);
  a63=(a63+a35);
  a61=(a11*a61);
  a63=(a63+a61);
  a63=(a63*a11);
  a46=(a46+a63);
  a46=(a46/a42);
  a46=(a46/a42);
  if (res[10]!=0) res[10][0]=a46;
  if (res[10]!=0) res[10][1]=a46;
  if (res[11]!=0) res[11][0]=a45;
  if (res[11]!=0) res[11][1]=a45;
  a37=(a37+a20);
  a37=(a37/a42);
  a37=(a37/a42);
  a42=9.9999999999999998e-13;
  a42=(a42*a37);
  a37=(a37+a42);
  a37=sqrt(a37);
  a39=(a39/a37);
  a39=(a39/a37);
  if (res[12]!=0) res[12][0]=a39;
  if (res[12]!=0) res[12][1]=a39;
  a45=(a45/a37);
  a22=(a45/a22);
  a22=(a22*a45);
  a22=sqrt(a22);
  a45=(a45/a22);
  if (res[13]!=0) res[13][0]=a45;
  if (res[13]!=0) res[13][1]=a45;
  a47=(-a47);
  if (res[14]!=0) res[14][0]=a47;
  a58=(a58/a57);
  a58=casadi_fmin(a02,a58);
  a60=(a60/a17);
  a58=casadi_fmin(a58,a60);
  if (res[15]!=0) res[15][0]=a58;
  a43=(a43/a00);
  a02=casadi_fmin(a02,a43);
  a07=(a07/a40);
  a02=casadi_fmin(a02,a07);
  if (res[16]!=0) res[16][0]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_extremes_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_extremes_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_extremes_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_metric_extremes_n_in(void) { return 12;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_metric_extremes_n_out(void) { return 17;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_metric_extremes_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_metric_extremes_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "contact_link";
    case 3: return "side";
    case 4: return "object_mass";
    case 5: return "object_inertia";
    case 6: return "q_obj";
    case 7: return "rho";
    case 8: return "wheel_offset";
    case 9: return "free";
    case 10: return "free_lost";
    case 11: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_metric_extremes_name_out(casadi_int i) {
  switch (i) {
    case 0: return "norm_a_obj_kept";
    case 1: return "tau_norm_a_obj_kept";
    case 2: return "norm_qdd_kept";
    case 3: return "tau_norm_qdd_kept";
    case 4: return "norm_lambda_kept";
    case 5: return "tau_norm_lambda_kept";
    case 6: return "norm_a_obj_lost";
    case 7: return "tau_norm_a_obj_lost";
    case 8: return "norm_qdd_lost";
    case 9: return "tau_norm_qdd_lost";
    case 10: return "norm_lambda_lost";
    case 11: return "tau_norm_lambda_lost";
    case 12: return "sr_kept";
    case 13: return "tau_sr_kept";
    case 14: return "contact_from_tau";
    case 15: return "pivot_ratio_kept";
    case 16: return "pivot_ratio_lost";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_metric_extremes_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s4;
    case 7: return casadi_s2;
    case 8: return casadi_s2;
    case 9: return casadi_s4;
    case 10: return casadi_s4;
    case 11: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_metric_extremes_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s5;
    case 2: return casadi_s2;
    case 3: return casadi_s5;
    case 4: return casadi_s2;
    case 5: return casadi_s5;
    case 6: return casadi_s2;
    case 7: return casadi_s5;
    case 8: return casadi_s2;
    case 9: return casadi_s5;
    case 10: return casadi_s2;
    case 11: return casadi_s5;
    case 12: return casadi_s2;
    case 13: return casadi_s5;
    case 14: return casadi_s3;
    case 15: return casadi_s3;
    case 16: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12;
  if (sz_res) *sz_res = 17;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_extremes_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 17*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_metric_extremes(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[12];
  casadi_real* r[17];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 67);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 12; ++k) a[k] = 0;
  for (k = 0; k < 17; ++k) r[k] = 0;
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
    r[0] = res[0] + i * 2;
    r[1] = res[1] + i * 2;
    r[2] = res[2] + i * 2;
    r[3] = res[3] + i * 2;
    r[4] = res[4] + i * 2;
    r[5] = res[5] + i * 2;
    r[6] = res[6] + i * 2;
    r[7] = res[7] + i * 2;
    r[8] = res[8] + i * 2;
    r[9] = res[9] + i * 2;
    r[10] = res[10] + i * 2;
    r[11] = res[11] + i * 2;
    r[12] = res[12] + i * 2;
    r[13] = res[13] + i * 2;
    r[14] = res[14] + i * 1;
    r[15] = res[15] + i * 1;
    r[16] = res[16] + i * 1;
    if (snakecg_na1_metric_extremes(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
