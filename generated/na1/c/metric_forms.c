/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_forms() of
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
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[0]? arg[0][2] : 0;
  a02=sin(a01);
  a03=(a00*a02);
  a04=arg[2]? arg[2][1] : 0;
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a02*a06);
  a01=cos(a01);
  a05=sin(a05);
  a08=(a01*a05);
  a07=(a07+a08);
  a09=(a04*a07);
  a03=(a03+a09);
  a09=arg[3]? arg[3][0] : 0;
  a10=(a03*a09);
  a11=arg[4]? arg[4][0] : 0;
  a12=(a10/a11);
  a13=arg[9]? arg[9][0] : 0;
  a14=(a00+a04);
  a15=(a10*a14);
  a16=arg[1]? arg[1][10] : 0;
  a17=(a06*a02);
  a08=(a08+a17);
  a17=(a16*a08);
  a18=arg[1]? arg[1][8] : 0;
  a19=(a17/a18);
  a20=arg[1]? arg[1][15] : 0;
  a21=casadi_sq(a19);
  a21=(a21*a18);
  a21=(a20-a21);
  a06=(a01*a06);
  a05=(a02*a05);
  a06=(a06-a05);
  a16=(a16*a06);
  a05=(a16/a18);
  a22=casadi_sq(a05);
  a22=(a22*a18);
  a21=(a21-a22);
  a22=(a06*a01);
  a23=(a08*a02);
  a22=(a22+a23);
  a23=arg[1]? arg[1][12] : 0;
  a22=(a22*a23);
  a23=(a22+a20);
  a24=arg[1]? arg[1][9] : 0;
  a25=(a24*a02);
  a25=(a17+a25);
  a26=(a25/a18);
  a27=(a19*a26);
  a27=(a27*a18);
  a27=(a23-a27);
  a24=(a24*a01);
  a24=(a16+a24);
  a28=(a24/a18);
  a29=(a05*a28);
  a29=(a29*a18);
  a27=(a27-a29);
  a29=arg[1]? arg[1][14] : 0;
  a22=(a22+a29);
  a22=(a22+a23);
  a29=casadi_sq(a26);
  a29=(a29*a18);
  a29=(a22-a29);
  a30=casadi_sq(a28);
  a30=(a30*a18);
  a29=(a29-a30);
  a27=(a27/a29);
  a30=casadi_sq(a27);
  a30=(a30*a29);
  a21=(a21-a30);
  a30=(a19/a21);
  a31=(a27/a21);
  a32=(a26*a31);
  a30=(a30-a32);
  a32=(a15*a30);
  a33=(a00*a01);
  a34=(a04*a06);
  a33=(a33+a34);
  a34=(a33*a09);
  a35=(a34*a14);
  a36=(a28*a31);
  a37=(a05/a21);
  a36=(a36-a37);
  a37=(a35*a36);
  a32=(a32-a37);
  a37=arg[0]? arg[0][1] : 0;
  a38=arg[1]? arg[1][2] : 0;
  a39=arg[1]? arg[1][6] : 0;
  a38=(a38-a39);
  a40=(a38*a02);
  a40=(a37+a40);
  a41=arg[1]? arg[1][7] : 0;
  a08=(a08*a41);
  a40=(a40+a08);
  a42=(a37-a40);
  a43=(a04*a42);
  a43=(a10*a43);
  a44=arg[0]? arg[0][0] : 0;
  a38=(a01*a38);
  a38=(a44+a38);
  a45=(a06*a41);
  a38=(a38+a45);
  a46=(a38-a44);
  a47=(a04*a46);
  a47=(a34*a47);
  a43=(a43-a47);
  a39=(a39*a00);
  a41=(a41*a04);
  a39=(a39+a41);
  a41=(a09*a39);
  a47=casadi_sq(a03);
  a47=(a41*a47);
  a48=casadi_sq(a33);
  a41=(a41*a48);
  a47=(a47+a41);
  a41=arg[6]? arg[6][2] : 0;
  a48=cos(a41);
  a49=arg[7]? arg[7][1] : 0;
  a50=(a48*a49);
  a41=sin(a41);
  a51=arg[7]? arg[7][0] : 0;
  a52=(a41*a51);
  a50=(a50+a52);
  a52=arg[6]? arg[6][1] : 0;
  a52=(a50+a52);
  a03=(a03*a39);
  a52=(a52+a03);
  a37=(a37*a00);
  a40=(a40*a04);
  a37=(a37+a40);
  a52=(a52-a37);
  a52=(a10*a52);
  a47=(a47-a52);
  a48=(a48*a51);
  a41=(a41*a49);
  a48=(a48-a41);
  a41=arg[6]? arg[6][0] : 0;
  a41=(a48+a41);
  a39=(a33*a39);
  a41=(a41+a39);
  a44=(a44*a00);
  a38=(a38*a04);
  a44=(a44+a38);
  a41=(a41-a44);
  a41=(a34*a41);
  a47=(a47-a41);
  a14=(a47*a14);
  a43=(a43+a14);
  a14=(a43*a31);
  a32=(a32-a14);
  a47=(a47*a04);
  a14=(a04*a08);
  a14=(a10*a14);
  a04=(a04*a45);
  a04=(a34*a04);
  a14=(a14+a04);
  a47=(a47-a14);
  a14=(a47/a21);
  a32=(a32+a14);
  a32=(a13*a32);
  a14=(a15/a18);
  a04=(a26*a15);
  a04=(a43+a04);
  a41=(a28*a35);
  a04=(a04+a41);
  a41=(a04/a29);
  a44=(a19*a15);
  a44=(a47+a44);
  a38=(a05*a35);
  a44=(a44+a38);
  a04=(a27*a04);
  a44=(a44-a04);
  a44=(a44/a21);
  a04=(a27*a44);
  a41=(a41-a04);
  a04=(a26*a41);
  a14=(a14+a04);
  a04=(a19*a44);
  a14=(a14+a04);
  a04=(a15*a14);
  a38=(a35/a18);
  a00=(a28*a41);
  a38=(a38+a00);
  a00=(a05*a44);
  a38=(a38+a00);
  a00=(a35*a38);
  a04=(a04+a00);
  a00=(a43*a41);
  a04=(a04+a00);
  a00=(a47*a44);
  a04=(a04+a00);
  a00=(a10*a12);
  a39=(a34/a11);
  a34=(a34*a39);
  a00=(a00+a34);
  a33=(a33*a48);
  a33=(a33*a09);
  a10=(a10*a50);
  a33=(a33+a10);
  a10=arg[5]? arg[5][0] : 0;
  a50=(a33/a10);
  a33=(a33*a50);
  a00=(a00+a33);
  a04=(a04+a00);
  a00=(a13*a04);
  a00=(a00*a13);
  a33=1.;
  a09=(a33-a13);
  a00=(a00+a09);
  a09=arg[10]? arg[10][0] : 0;
  a48=(a09*a13);
  a00=(a00+a48);
  a48=(a32/a00);
  a34=arg[9]? arg[9][1] : 0;
  a49=arg[8]? arg[8][0] : 0;
  a51=(a49*a41);
  a52=(a02*a14);
  a37=(a01*a38);
  a52=(a52+a37);
  a51=(a51-a52);
  a52=(a34*a51);
  a52=(a52*a13);
  a52=(a52/a00);
  a37=(a01*a36);
  a40=(a02*a30);
  a37=(a37-a40);
  a40=(a49*a31);
  a37=(a37-a40);
  a37=(a34*a37);
  a40=(a52*a32);
  a37=(a37-a40);
  a40=(a01/a18);
  a03=(a26*a02);
  a03=(a49-a03);
  a53=(a28*a01);
  a03=(a03-a53);
  a53=(a03/a29);
  a54=(a19*a02);
  a55=(a05*a01);
  a54=(a54+a55);
  a03=(a27*a03);
  a54=(a54+a03);
  a54=(a54/a21);
  a03=(a27*a54);
  a53=(a53+a03);
  a03=(a28*a53);
  a40=(a40-a03);
  a03=(a05*a54);
  a40=(a40+a03);
  a03=(a01*a40);
  a55=(a26*a53);
  a56=(a02/a18);
  a55=(a55-a56);
  a56=(a19*a54);
  a55=(a55-a56);
  a56=(a02*a55);
  a03=(a03-a56);
  a56=(a49*a53);
  a03=(a03+a56);
  a56=(a34*a03);
  a56=(a56*a34);
  a57=(a33-a34);
  a56=(a56+a57);
  a57=(a09*a34);
  a56=(a56+a57);
  a57=casadi_sq(a52);
  a57=(a57*a00);
  a57=(a56-a57);
  a58=(a37/a57);
  a59=arg[9]? arg[9][2] : 0;
  a60=(a06*a40);
  a61=(a07*a55);
  a60=(a60-a61);
  a46=(a06*a46);
  a42=(a07*a42);
  a46=(a46-a42);
  a42=arg[8]? arg[8][1] : 0;
  a46=(a46+a42);
  a61=(a46*a53);
  a60=(a60+a61);
  a08=(a07*a08);
  a45=(a06*a45);
  a08=(a08+a45);
  a08=(a08+a42);
  a42=(a08*a54);
  a60=(a60-a42);
  a42=(a59*a60);
  a42=(a42*a34);
  a34=(a46*a41);
  a45=(a07*a14);
  a61=(a06*a38);
  a45=(a45+a61);
  a34=(a34-a45);
  a45=(a08*a44);
  a34=(a34+a45);
  a45=(a59*a34);
  a45=(a45*a13);
  a45=(a45/a00);
  a13=(a45*a52);
  a13=(a13*a00);
  a42=(a42-a13);
  a42=(a42/a57);
  a13=(a06*a36);
  a61=(a07*a30);
  a13=(a13-a61);
  a61=(a46*a31);
  a13=(a13-a61);
  a61=(a08/a21);
  a13=(a13+a61);
  a13=(a59*a13);
  a32=(a45*a32);
  a13=(a13-a32);
  a37=(a42*a37);
  a13=(a13-a37);
  a37=(a06/a18);
  a32=(a26*a07);
  a32=(a46-a32);
  a61=(a28*a06);
  a32=(a32-a61);
  a29=(a32/a29);
  a61=(a19*a07);
  a61=(a08-a61);
  a62=(a05*a06);
  a61=(a61-a62);
  a32=(a27*a32);
  a61=(a61-a32);
  a61=(a61/a21);
  a27=(a27*a61);
  a29=(a29-a27);
  a28=(a28*a29);
  a37=(a37-a28);
  a05=(a05*a61);
  a37=(a37-a05);
  a06=(a06*a37);
  a26=(a26*a29);
  a05=(a07/a18);
  a26=(a26-a05);
  a19=(a19*a61);
  a26=(a26+a19);
  a07=(a07*a26);
  a06=(a06-a07);
  a46=(a46*a29);
  a06=(a06+a46);
  a08=(a08*a61);
  a06=(a06+a08);
  a08=(a59*a06);
  a08=(a08*a59);
  a46=(a33-a59);
  a08=(a08+a46);
  a09=(a09*a59);
  a08=(a08+a09);
  a09=casadi_sq(a45);
  a09=(a09*a00);
  a09=(a08-a09);
  a00=casadi_sq(a42);
  a00=(a00*a57);
  a09=(a09-a00);
  a13=(a13/a09);
  a42=(a42*a13);
  a58=(a58-a42);
  a52=(a52*a58);
  a48=(a48-a52);
  a45=(a45*a13);
  a48=(a48-a45);
  a12=(a12*a48);
  a45=(a12*a11);
  a45=(a45*a12);
  a39=(a39*a48);
  a11=(a39*a11);
  a11=(a11*a39);
  a45=(a45+a11);
  a50=(a50*a48);
  a10=(a50*a10);
  a10=(a10*a50);
  a45=(a45+a10);
  if (res[0]!=0) res[0][0]=a45;
  a14=(a14*a48);
  a45=(a55*a58);
  a14=(a14+a45);
  a45=(a26*a13);
  a14=(a14+a45);
  a30=(a30-a14);
  a14=(a30*a18);
  a41=(a41*a48);
  a45=(a53*a58);
  a41=(a41+a45);
  a45=(a29*a13);
  a41=(a41+a45);
  a31=(a31+a41);
  a41=(a31*a25);
  a14=(a14+a41);
  a21=(1./a21);
  a41=(a54*a58);
  a44=(a44*a48);
  a41=(a41-a44);
  a44=(a61*a13);
  a41=(a41-a44);
  a41=(a21+a41);
  a44=(a41*a17);
  a14=(a14-a44);
  a14=(a14*a30);
  a38=(a38*a48);
  a44=(a40*a58);
  a38=(a38-a44);
  a44=(a37*a13);
  a38=(a38-a44);
  a36=(a36+a38);
  a18=(a36*a18);
  a38=(a31*a24);
  a18=(a18-a38);
  a38=(a41*a16);
  a18=(a18+a38);
  a18=(a18*a36);
  a14=(a14+a18);
  a24=(a36*a24);
  a25=(a30*a25);
  a24=(a24-a25);
  a22=(a31*a22);
  a24=(a24-a22);
  a22=(a41*a23);
  a24=(a24+a22);
  a24=(a24*a31);
  a14=(a14-a24);
  a36=(a36*a16);
  a30=(a30*a17);
  a36=(a36-a30);
  a31=(a31*a23);
  a36=(a36-a31);
  a20=(a41*a20);
  a36=(a36+a20);
  a36=(a36*a41);
  a14=(a14+a36);
  if (res[1]!=0) res[1][0]=a14;
  a04=(a48*a04);
  a51=(a58*a51);
  a04=(a04+a51);
  a34=(a13*a34);
  a04=(a04+a34);
  a04=(a04*a48);
  a55=(a15*a55);
  a40=(a35*a40);
  a55=(a55-a40);
  a53=(a43*a53);
  a55=(a55+a53);
  a54=(a47*a54);
  a55=(a55-a54);
  a55=(a48*a55);
  a03=(a58*a03);
  a55=(a55+a03);
  a60=(a13*a60);
  a55=(a55+a60);
  a55=(a55*a58);
  a04=(a04+a55);
  a15=(a15*a26);
  a35=(a35*a37);
  a15=(a15-a35);
  a43=(a43*a29);
  a15=(a15+a43);
  a47=(a47*a61);
  a15=(a15+a47);
  a15=(a48*a15);
  a01=(a01*a37);
  a02=(a02*a26);
  a01=(a01-a02);
  a49=(a49*a29);
  a01=(a01+a49);
  a58=(a58*a01);
  a15=(a15+a58);
  a06=(a13*a06);
  a15=(a15+a06);
  a15=(a15*a13);
  a04=(a04+a15);
  if (res[2]!=0) res[2][0]=a04;
  if (res[3]!=0) res[3][0]=a21;
  a48=(-a48);
  if (res[4]!=0) res[4][0]=a48;
  a57=(a57/a56);
  a33=casadi_fmin(a33,a57);
  a09=(a09/a08);
  a33=casadi_fmin(a33,a09);
  if (res[5]!=0) res[5][0]=a33;
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
