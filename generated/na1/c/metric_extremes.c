/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_extremes() of
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
  a14=(a13*a32);
  a04=(a15/a18);
  a41=(a26*a15);
  a41=(a43+a41);
  a44=(a28*a35);
  a41=(a41+a44);
  a44=(a41/a29);
  a38=(a19*a15);
  a38=(a47+a38);
  a00=(a05*a35);
  a38=(a38+a00);
  a41=(a27*a41);
  a38=(a38-a41);
  a38=(a38/a21);
  a41=(a27*a38);
  a44=(a44-a41);
  a41=(a26*a44);
  a04=(a04+a41);
  a41=(a19*a38);
  a04=(a04+a41);
  a41=(a15*a04);
  a00=(a35/a18);
  a39=(a28*a44);
  a00=(a00+a39);
  a39=(a05*a38);
  a00=(a00+a39);
  a39=(a35*a00);
  a41=(a41+a39);
  a39=(a43*a44);
  a41=(a41+a39);
  a39=(a47*a38);
  a41=(a41+a39);
  a39=(a10*a12);
  a49=(a34/a11);
  a34=(a34*a49);
  a39=(a39+a34);
  a33=(a33*a48);
  a33=(a33*a09);
  a10=(a10*a50);
  a33=(a33+a10);
  a10=arg[5]? arg[5][0] : 0;
  a50=(a33/a10);
  a33=(a33*a50);
  a39=(a39+a33);
  a41=(a41+a39);
  a39=(a13*a41);
  a39=(a39*a13);
  a33=1.;
  a09=(a33-a13);
  a39=(a39+a09);
  a09=arg[11]? arg[11][0] : 0;
  a48=(a09*a13);
  a39=(a39+a48);
  a48=(a14/a39);
  a34=arg[9]? arg[9][1] : 0;
  a51=arg[8]? arg[8][0] : 0;
  a52=(a51*a44);
  a37=(a02*a04);
  a40=(a01*a00);
  a37=(a37+a40);
  a52=(a52-a37);
  a37=(a34*a52);
  a37=(a37*a13);
  a37=(a37/a39);
  a40=(a01*a36);
  a03=(a02*a30);
  a40=(a40-a03);
  a03=(a51*a31);
  a40=(a40-a03);
  a03=(a34*a40);
  a53=(a37*a14);
  a03=(a03-a53);
  a53=(a01/a18);
  a54=(a26*a02);
  a54=(a51-a54);
  a55=(a28*a01);
  a54=(a54-a55);
  a55=(a54/a29);
  a56=(a19*a02);
  a57=(a05*a01);
  a56=(a56+a57);
  a54=(a27*a54);
  a56=(a56+a54);
  a56=(a56/a21);
  a54=(a27*a56);
  a55=(a55+a54);
  a54=(a28*a55);
  a53=(a53-a54);
  a54=(a05*a56);
  a53=(a53+a54);
  a54=(a01*a53);
  a57=(a26*a55);
  a58=(a02/a18);
  a57=(a57-a58);
  a58=(a19*a56);
  a57=(a57-a58);
  a58=(a02*a57);
  a54=(a54-a58);
  a58=(a51*a55);
  a54=(a54+a58);
  a58=(a34*a54);
  a58=(a58*a34);
  a59=(a33-a34);
  a58=(a58+a59);
  a59=(a09*a34);
  a58=(a58+a59);
  a59=casadi_sq(a37);
  a59=(a59*a39);
  a59=(a58-a59);
  a60=(a03/a59);
  a61=arg[9]? arg[9][2] : 0;
  a62=(a06*a53);
  a63=(a07*a57);
  a62=(a62-a63);
  a46=(a06*a46);
  a42=(a07*a42);
  a46=(a46-a42);
  a42=arg[8]? arg[8][1] : 0;
  a46=(a46+a42);
  a63=(a46*a55);
  a62=(a62+a63);
  a08=(a07*a08);
  a45=(a06*a45);
  a08=(a08+a45);
  a08=(a08+a42);
  a42=(a08*a56);
  a62=(a62-a42);
  a42=(a61*a62);
  a42=(a42*a34);
  a34=(a46*a44);
  a45=(a07*a04);
  a63=(a06*a00);
  a45=(a45+a63);
  a34=(a34-a45);
  a45=(a08*a38);
  a34=(a34+a45);
  a45=(a61*a34);
  a45=(a45*a13);
  a45=(a45/a39);
  a13=(a45*a37);
  a13=(a13*a39);
  a42=(a42-a13);
  a42=(a42/a59);
  a13=(a06*a36);
  a63=(a07*a30);
  a13=(a13-a63);
  a63=(a46*a31);
  a13=(a13-a63);
  a63=(a08/a21);
  a13=(a13+a63);
  a63=(a61*a13);
  a14=(a45*a14);
  a63=(a63-a14);
  a03=(a42*a03);
  a63=(a63-a03);
  a03=(a06/a18);
  a14=(a26*a07);
  a14=(a46-a14);
  a64=(a28*a06);
  a14=(a14-a64);
  a29=(a14/a29);
  a64=(a19*a07);
  a64=(a08-a64);
  a65=(a05*a06);
  a64=(a64-a65);
  a14=(a27*a14);
  a64=(a64-a14);
  a64=(a64/a21);
  a27=(a27*a64);
  a29=(a29-a27);
  a28=(a28*a29);
  a03=(a03-a28);
  a05=(a05*a64);
  a03=(a03-a05);
  a06=(a06*a03);
  a26=(a26*a29);
  a05=(a07/a18);
  a26=(a26-a05);
  a19=(a19*a64);
  a26=(a26+a19);
  a07=(a07*a26);
  a06=(a06-a07);
  a46=(a46*a29);
  a06=(a06+a46);
  a08=(a08*a64);
  a06=(a06+a08);
  a08=(a61*a06);
  a08=(a08*a61);
  a46=(a33-a61);
  a08=(a08+a46);
  a61=(a09*a61);
  a08=(a08+a61);
  a61=casadi_sq(a45);
  a61=(a61*a39);
  a61=(a08-a61);
  a39=casadi_sq(a42);
  a39=(a39*a59);
  a61=(a61-a39);
  a63=(a63/a61);
  a42=(a42*a63);
  a60=(a60-a42);
  a37=(a37*a60);
  a48=(a48-a37);
  a45=(a45*a63);
  a48=(a48-a45);
  a45=(a12*a48);
  a37=(a45*a11);
  a37=(a37*a45);
  a45=(a49*a48);
  a42=(a45*a11);
  a42=(a42*a45);
  a37=(a37+a42);
  a42=(a50*a48);
  a45=(a42*a10);
  a45=(a45*a42);
  a37=(a37+a45);
  a45=(1./a21);
  a42=sqrt(a45);
  a39=(a37/a42);
  a39=(a39/a42);
  if (res[0]!=0) res[0][0]=a39;
  if (res[0]!=0) res[0][1]=a39;
  a46=(1./a42);
  if (res[1]!=0) res[1][0]=a46;
  if (res[1]!=0) res[1][1]=a46;
  a07=(a04*a48);
  a19=(a57*a60);
  a07=(a07+a19);
  a19=(a26*a63);
  a07=(a07+a19);
  a07=(a30-a07);
  a19=(a07*a18);
  a05=(a44*a48);
  a28=(a55*a60);
  a05=(a05+a28);
  a28=(a29*a63);
  a05=(a05+a28);
  a05=(a31+a05);
  a28=(a05*a25);
  a19=(a19+a28);
  a28=(a56*a60);
  a27=(a38*a48);
  a28=(a28-a27);
  a27=(a64*a63);
  a28=(a28-a27);
  a28=(a45+a28);
  a27=(a28*a17);
  a19=(a19-a27);
  a19=(a19*a07);
  a27=(a00*a48);
  a14=(a53*a60);
  a27=(a27-a14);
  a14=(a03*a63);
  a27=(a27-a14);
  a27=(a36+a27);
  a14=(a27*a18);
  a65=(a05*a24);
  a14=(a14-a65);
  a65=(a28*a16);
  a14=(a14+a65);
  a14=(a14*a27);
  a19=(a19+a14);
  a14=(a27*a24);
  a65=(a07*a25);
  a14=(a14-a65);
  a65=(a05*a22);
  a14=(a14-a65);
  a65=(a28*a23);
  a14=(a14+a65);
  a14=(a14*a05);
  a19=(a19-a14);
  a27=(a27*a16);
  a07=(a07*a17);
  a27=(a27-a07);
  a05=(a05*a23);
  a27=(a27-a05);
  a05=(a28*a20);
  a27=(a27+a05);
  a27=(a27*a28);
  a19=(a19+a27);
  a27=(a19/a42);
  a27=(a27/a42);
  if (res[2]!=0) res[2][0]=a27;
  if (res[2]!=0) res[2][1]=a27;
  if (res[3]!=0) res[3][0]=a46;
  if (res[3]!=0) res[3][1]=a46;
  a27=(a48*a41);
  a28=(a60*a52);
  a27=(a27+a28);
  a28=(a63*a34);
  a27=(a27+a28);
  a27=(a27*a48);
  a28=(a15*a57);
  a05=(a35*a53);
  a28=(a28-a05);
  a05=(a43*a55);
  a28=(a28+a05);
  a05=(a47*a56);
  a28=(a28-a05);
  a05=(a48*a28);
  a07=(a60*a54);
  a05=(a05+a07);
  a07=(a63*a62);
  a05=(a05+a07);
  a05=(a05*a60);
  a27=(a27+a05);
  a15=(a15*a26);
  a35=(a35*a03);
  a15=(a15-a35);
  a43=(a43*a29);
  a15=(a15+a43);
  a47=(a47*a64);
  a15=(a15+a47);
  a47=(a48*a15);
  a01=(a01*a03);
  a02=(a02*a26);
  a01=(a01-a02);
  a51=(a51*a29);
  a01=(a01+a51);
  a60=(a60*a01);
  a47=(a47+a60);
  a60=(a63*a06);
  a47=(a47+a60);
  a47=(a47*a63);
  a27=(a27+a47);
  a27=(a27/a42);
  a27=(a27/a42);
  if (res[4]!=0) res[4][0]=a27;
  if (res[4]!=0) res[4][1]=a27;
  if (res[5]!=0) res[5][0]=a46;
  if (res[5]!=0) res[5][1]=a46;
  a27=arg[10]? arg[10][0] : 0;
  a32=(a27*a32);
  a47=(a27*a41);
  a47=(a47*a27);
  a63=(a33-a27);
  a47=(a47+a63);
  a63=(a09*a27);
  a47=(a47+a63);
  a63=(a32/a47);
  a60=arg[10]? arg[10][1] : 0;
  a51=(a60*a52);
  a51=(a51*a27);
  a51=(a51/a47);
  a40=(a60*a40);
  a02=(a51*a32);
  a40=(a40-a02);
  a02=(a60*a54);
  a02=(a02*a60);
  a43=(a33-a60);
  a02=(a02+a43);
  a43=(a09*a60);
  a02=(a02+a43);
  a43=casadi_sq(a51);
  a43=(a43*a47);
  a43=(a02-a43);
  a35=(a40/a43);
  a05=arg[10]? arg[10][2] : 0;
  a07=(a05*a62);
  a07=(a07*a60);
  a60=(a05*a34);
  a60=(a60*a27);
  a60=(a60/a47);
  a27=(a60*a51);
  a27=(a27*a47);
  a07=(a07-a27);
  a07=(a07/a43);
  a13=(a05*a13);
  a32=(a60*a32);
  a13=(a13-a32);
  a40=(a07*a40);
  a13=(a13-a40);
  a40=(a05*a06);
  a40=(a40*a05);
  a32=(a33-a05);
  a40=(a40+a32);
  a09=(a09*a05);
  a40=(a40+a09);
  a09=casadi_sq(a60);
  a09=(a09*a47);
  a09=(a40-a09);
  a47=casadi_sq(a07);
  a47=(a47*a43);
  a09=(a09-a47);
  a13=(a13/a09);
  a07=(a07*a13);
  a35=(a35-a07);
  a51=(a51*a35);
  a63=(a63-a51);
  a60=(a60*a13);
  a63=(a63-a60);
  a12=(a12*a63);
  a60=(a12*a11);
  a60=(a60*a12);
  a49=(a49*a63);
  a11=(a49*a11);
  a11=(a11*a49);
  a60=(a60+a11);
  a50=(a50*a63);
  a10=(a50*a10);
  a10=(a10*a50);
  a60=(a60+a10);
  a60=(a60/a42);
  a60=(a60/a42);
  if (res[6]!=0) res[6][0]=a60;
  if (res[6]!=0) res[6][1]=a60;
  if (res[7]!=0) res[7][0]=a46;
  if (res[7]!=0) res[7][1]=a46;
  a04=(a04*a63);
  a57=(a57*a35);
  a04=(a04+a57);
  a26=(a26*a13);
  a04=(a04+a26);
  a30=(a30-a04);
  a04=(a30*a18);
  a44=(a44*a63);
  a55=(a55*a35);
  a44=(a44+a55);
  a29=(a29*a13);
  a44=(a44+a29);
  a31=(a31+a44);
  a44=(a31*a25);
  a04=(a04+a44);
  a56=(a56*a35);
  a38=(a38*a63);
  a56=(a56-a38);
  a64=(a64*a13);
  a56=(a56-a64);
  a45=(a45+a56);
  a56=(a45*a17);
  a04=(a04-a56);
  a04=(a04*a30);
  a00=(a00*a63);
  a53=(a53*a35);
  a00=(a00-a53);
  a03=(a03*a13);
  a00=(a00-a03);
  a36=(a36+a00);
  a18=(a36*a18);
  a00=(a31*a24);
  a18=(a18-a00);
  a00=(a45*a16);
  a18=(a18+a00);
  a18=(a18*a36);
  a04=(a04+a18);
  a24=(a36*a24);
  a25=(a30*a25);
  a24=(a24-a25);
  a22=(a31*a22);
  a24=(a24-a22);
  a22=(a45*a23);
  a24=(a24+a22);
  a24=(a24*a31);
  a04=(a04-a24);
  a36=(a36*a16);
  a30=(a30*a17);
  a36=(a36-a30);
  a31=(a31*a23);
  a36=(a36-a31);
  a20=(a45*a20);
  a36=(a36+a20);
  a36=(a36*a45);
  a04=(a04+a36);
  a04=(a04/a42);
  a04=(a04/a42);
  if (res[8]!=0) res[8][0]=a04;
  if (res[8]!=0) res[8][1]=a04;
  if (res[9]!=0) res[9][0]=a46;
  if (res[9]!=0) res[9][1]=a46;
  a41=(a63*a41);
  a52=(a35*a52);
  a41=(a41+a52);
  a34=(a13*a34);
  a41=(a41+a34);
  a41=(a41*a63);
  a28=(a63*a28);
  a54=(a35*a54);
  a28=(a28+a54);
  a62=(a13*a62);
  a28=(a28+a62);
  a28=(a28*a35);
  a41=(a41+a28);
  a63=(a63*a15);
  a35=(a35*a01);
  a63=(a63+a35);
  a06=(a13*a06);
  a63=(a63+a06);
  a63=(a63*a13);
  a41=(a41+a63);
  a41=(a41/a42);
  a41=(a41/a42);
  if (res[10]!=0) res[10][0]=a41;
  if (res[10]!=0) res[10][1]=a41;
  if (res[11]!=0) res[11][0]=a46;
  if (res[11]!=0) res[11][1]=a46;
  a37=(a37+a19);
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
  a46=(a46/a37);
  a21=(a46/a21);
  a21=(a21*a46);
  a21=sqrt(a21);
  a46=(a46/a21);
  if (res[13]!=0) res[13][0]=a46;
  if (res[13]!=0) res[13][1]=a46;
  a48=(-a48);
  if (res[14]!=0) res[14][0]=a48;
  a59=(a59/a58);
  a59=casadi_fmin(a33,a59);
  a61=(a61/a08);
  a59=casadi_fmin(a59,a61);
  if (res[15]!=0) res[15][0]=a59;
  a43=(a43/a02);
  a33=casadi_fmin(a33,a43);
  a09=(a09/a40);
  a33=casadi_fmin(a33,a09);
  if (res[16]!=0) res[16][0]=a33;
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
