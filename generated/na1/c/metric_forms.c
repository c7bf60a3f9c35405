/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_forms() of
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
  #define CASADI_PREFIX(ID) snakecg_na1_metric_forms_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na1_metric_forms_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};

/* snakecg_na1_metric_forms:(q[4],K[16],contact_link[2],side,object_mass,object_inertia,q_obj[3],rho[2],wheel_offset[2],free[3],regularization)->(omega_tau,xi_tau,lambda_form_tau,input_metric,contact_from_tau,pivot_ratio) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62;
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
  a33=(a11*a33);
  a12=(a13/a19);
  a05=(a27*a13);
  a05=(a43+a05);
  a46=(a29*a35);
  a05=(a05+a46);
  a46=(a05/a30);
  a44=(a20*a13);
  a44=(a41+a44);
  a38=(a16*a35);
  a44=(a44+a38);
  a05=(a28*a05);
  a44=(a44-a05);
  a44=(a44/a22);
  a05=(a28*a44);
  a46=(a46-a05);
  a05=(a27*a46);
  a12=(a12+a05);
  a05=(a20*a44);
  a12=(a12+a05);
  a05=(a13*a12);
  a38=(a35/a19);
  a01=(a29*a46);
  a38=(a38+a01);
  a01=(a16*a44);
  a38=(a38+a01);
  a01=(a35*a38);
  a05=(a05+a01);
  a01=(a43*a46);
  a05=(a05+a01);
  a01=(a41*a44);
  a05=(a05+a01);
  a01=(a08*a10);
  a39=(a34/a09);
  a34=(a34*a39);
  a01=(a01+a34);
  a02=(a02*a47);
  a02=(a02*a07);
  a08=(a08*a49);
  a02=(a02+a08);
  a08=arg[5]? arg[5][0] : 0;
  a49=(a02/a08);
  a02=(a02*a49);
  a01=(a01+a02);
  a05=(a05+a01);
  a01=(a11*a05);
  a01=(a01*a11);
  a02=1.;
  a07=(a02-a11);
  a01=(a01+a07);
  a07=arg[10]? arg[10][0] : 0;
  a47=(a07*a11);
  a01=(a01+a47);
  a47=(a33/a01);
  a34=arg[9]? arg[9][1] : 0;
  a48=arg[8]? arg[8][0] : 0;
  a50=(a48*a46);
  a51=(a00*a12);
  a37=(a15*a38);
  a51=(a51+a37);
  a50=(a50-a51);
  a51=(a34*a50);
  a51=(a51*a11);
  a51=(a51/a01);
  a37=(a15*a36);
  a40=(a00*a31);
  a37=(a37-a40);
  a40=(a48*a32);
  a37=(a37-a40);
  a37=(a34*a37);
  a40=(a51*a33);
  a37=(a37-a40);
  a40=(a15/a19);
  a06=(a27*a00);
  a06=(a48-a06);
  a52=(a29*a15);
  a06=(a06-a52);
  a52=(a06/a30);
  a53=(a20*a00);
  a54=(a16*a15);
  a53=(a53+a54);
  a06=(a28*a06);
  a53=(a53+a06);
  a53=(a53/a22);
  a06=(a28*a53);
  a52=(a52+a06);
  a06=(a29*a52);
  a40=(a40-a06);
  a06=(a16*a53);
  a40=(a40+a06);
  a06=(a15*a40);
  a54=(a27*a52);
  a55=(a00/a19);
  a54=(a54-a55);
  a55=(a20*a53);
  a54=(a54-a55);
  a55=(a00*a54);
  a06=(a06-a55);
  a55=(a48*a52);
  a06=(a06+a55);
  a55=(a34*a06);
  a55=(a55*a34);
  a56=(a02-a34);
  a55=(a55+a56);
  a56=(a07*a34);
  a55=(a55+a56);
  a56=casadi_sq(a51);
  a56=(a56*a01);
  a56=(a55-a56);
  a57=(a37/a56);
  a58=arg[9]? arg[9][2] : 0;
  a59=cos(a04);
  a60=(a59*a40);
  a04=sin(a04);
  a61=(a04*a54);
  a60=(a60-a61);
  a45=(a59*a45);
  a42=(a04*a42);
  a45=(a45-a42);
  a42=arg[8]? arg[8][1] : 0;
  a45=(a45+a42);
  a61=(a45*a52);
  a60=(a60+a61);
  a17=(a04*a17);
  a03=(a59*a03);
  a17=(a17+a03);
  a17=(a17+a42);
  a42=(a17*a53);
  a60=(a60-a42);
  a42=(a58*a60);
  a42=(a42*a34);
  a34=(a45*a46);
  a03=(a04*a12);
  a61=(a59*a38);
  a03=(a03+a61);
  a34=(a34-a03);
  a03=(a17*a44);
  a34=(a34+a03);
  a03=(a58*a34);
  a03=(a03*a11);
  a03=(a03/a01);
  a11=(a03*a51);
  a11=(a11*a01);
  a42=(a42-a11);
  a42=(a42/a56);
  a11=(a59*a36);
  a61=(a04*a31);
  a11=(a11-a61);
  a61=(a45*a32);
  a11=(a11-a61);
  a61=(a17/a22);
  a11=(a11+a61);
  a11=(a58*a11);
  a33=(a03*a33);
  a11=(a11-a33);
  a37=(a42*a37);
  a11=(a11-a37);
  a37=(a59/a19);
  a33=(a27*a04);
  a33=(a45-a33);
  a61=(a29*a59);
  a33=(a33-a61);
  a30=(a33/a30);
  a61=(a20*a04);
  a61=(a17-a61);
  a62=(a16*a59);
  a61=(a61-a62);
  a33=(a28*a33);
  a61=(a61-a33);
  a61=(a61/a22);
  a28=(a28*a61);
  a30=(a30-a28);
  a29=(a29*a30);
  a37=(a37-a29);
  a16=(a16*a61);
  a37=(a37-a16);
  a59=(a59*a37);
  a27=(a27*a30);
  a16=(a04/a19);
  a27=(a27-a16);
  a20=(a20*a61);
  a27=(a27+a20);
  a04=(a04*a27);
  a59=(a59-a04);
  a45=(a45*a30);
  a59=(a59+a45);
  a17=(a17*a61);
  a59=(a59+a17);
  a17=(a58*a59);
  a17=(a17*a58);
  a45=(a02-a58);
  a17=(a17+a45);
  a07=(a07*a58);
  a17=(a17+a07);
  a07=casadi_sq(a03);
  a07=(a07*a01);
  a07=(a17-a07);
  a01=casadi_sq(a42);
  a01=(a01*a56);
  a07=(a07-a01);
  a11=(a11/a07);
  a42=(a42*a11);
  a57=(a57-a42);
  a51=(a51*a57);
  a47=(a47-a51);
  a03=(a03*a11);
  a47=(a47-a03);
  a10=(a10*a47);
  a03=(a10*a09);
  a03=(a03*a10);
  a39=(a39*a47);
  a09=(a39*a09);
  a09=(a09*a39);
  a03=(a03+a09);
  a49=(a49*a47);
  a08=(a49*a08);
  a08=(a08*a49);
  a03=(a03+a08);
  if (res[0]!=0) res[0][0]=a03;
  a12=(a12*a47);
  a03=(a54*a57);
  a12=(a12+a03);
  a03=(a27*a11);
  a12=(a12+a03);
  a31=(a31-a12);
  a12=(a31*a19);
  a46=(a46*a47);
  a03=(a52*a57);
  a46=(a46+a03);
  a03=(a30*a11);
  a46=(a46+a03);
  a32=(a32+a46);
  a46=(a32*a26);
  a12=(a12+a46);
  a22=(1./a22);
  a46=(a53*a57);
  a44=(a44*a47);
  a46=(a46-a44);
  a44=(a61*a11);
  a46=(a46-a44);
  a46=(a22+a46);
  a44=(a46*a18);
  a12=(a12-a44);
  a12=(a12*a31);
  a38=(a38*a47);
  a44=(a40*a57);
  a38=(a38-a44);
  a44=(a37*a11);
  a38=(a38-a44);
  a36=(a36+a38);
  a19=(a36*a19);
  a38=(a32*a25);
  a19=(a19-a38);
  a38=(a46*a14);
  a19=(a19+a38);
  a19=(a19*a36);
  a12=(a12+a19);
  a25=(a36*a25);
  a26=(a31*a26);
  a25=(a25-a26);
  a23=(a32*a23);
  a25=(a25-a23);
  a23=(a46*a24);
  a25=(a25+a23);
  a25=(a25*a32);
  a12=(a12-a25);
  a36=(a36*a14);
  a31=(a31*a18);
  a36=(a36-a31);
  a32=(a32*a24);
  a36=(a36-a32);
  a21=(a46*a21);
  a36=(a36+a21);
  a36=(a36*a46);
  a12=(a12+a36);
  if (res[1]!=0) res[1][0]=a12;
  a05=(a47*a05);
  a50=(a57*a50);
  a05=(a05+a50);
  a34=(a11*a34);
  a05=(a05+a34);
  a05=(a05*a47);
  a54=(a13*a54);
  a40=(a35*a40);
  a54=(a54-a40);
  a52=(a43*a52);
  a54=(a54+a52);
  a53=(a41*a53);
  a54=(a54-a53);
  a54=(a47*a54);
  a06=(a57*a06);
  a54=(a54+a06);
  a60=(a11*a60);
  a54=(a54+a60);
  a54=(a54*a57);
  a05=(a05+a54);
  a13=(a13*a27);
  a35=(a35*a37);
  a13=(a13-a35);
  a43=(a43*a30);
  a13=(a13+a43);
  a41=(a41*a61);
  a13=(a13+a41);
  a13=(a47*a13);
  a15=(a15*a37);
  a00=(a00*a27);
  a15=(a15-a00);
  a48=(a48*a30);
  a15=(a15+a48);
  a57=(a57*a15);
  a13=(a13+a57);
  a59=(a11*a59);
  a13=(a13+a59);
  a13=(a13*a11);
  a05=(a05+a13);
  if (res[2]!=0) res[2][0]=a05;
  if (res[3]!=0) res[3][0]=a22;
  a47=(-a47);
  if (res[4]!=0) res[4][0]=a47;
  a56=(a56/a55);
  a02=casadi_fmin(a02,a56);
  a07=(a07/a17);
  a02=casadi_fmin(a02,a07);
  if (res[5]!=0) res[5][0]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_forms_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_forms_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_metric_forms_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_metric_forms_n_in(void) { return 11;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_metric_forms_n_out(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_metric_forms_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_metric_forms_name_in(casadi_int i) {
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
    case 10: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_metric_forms_name_out(casadi_int i) {
  switch (i) {
    case 0: return "omega_tau";
    case 1: return "xi_tau";
    case 2: return "lambda_form_tau";
    case 3: return "input_metric";
    case 4: return "contact_from_tau";
    case 5: return "pivot_ratio";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_metric_forms_sparsity_in(casadi_int i) {
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
    case 10: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_metric_forms_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s3;
    case 2: return casadi_s3;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_metric_forms_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_metric_forms(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[11];
  casadi_real* r[6];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 64);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 11; ++k) a[k] = 0;
  for (k = 0; k < 6; ++k) r[k] = 0;
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
    r[0] = res[0] + i * 1;
    r[1] = res[1] + i * 1;
    r[2] = res[2] + i * 1;
    r[3] = res[3] + i * 1;
    r[4] = res[4] + i * 1;
    r[5] = res[5] + i * 1;
    if (snakecg_na1_metric_forms(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
