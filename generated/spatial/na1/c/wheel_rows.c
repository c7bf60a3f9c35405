/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for wheel_rows() of
 * generated/spatial/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: f2554e7caf7b43e45e9fb60d8118a375db06d8dd0e711f01c5b700b16dc8d2be
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp1_wheel_rows_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp1_wheel_rows_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};
static const casadi_int casadi_s3[3] = {6, 1, 1};
static const casadi_int casadi_s4[3] = {2, 7, 1};
static const casadi_int casadi_s5[3] = {2, 1, 1};

/* snakecg_sp1_wheel_rows:(q[8],v[7],K[71],wheel_points[6],wheel_heading[6])->(A[2x7],adot_v[2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61;
  a00=arg[0]? arg[0][6] : 0;
  a01=(2.*a00);
  a02=arg[0]? arg[0][5] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][3] : 0;
  a05=(2.*a04);
  a06=arg[0]? arg[0][4] : 0;
  a07=(a05*a06);
  a03=(a03+a07);
  a08=1.;
  a09=-2.;
  a10=casadi_sq(a06);
  a10=(a09*a10);
  a11=(a08+a10);
  a12=casadi_sq(a02);
  a12=(a09*a12);
  a11=(a11+a12);
  a13=arg[4]? arg[4][0] : 0;
  a14=(a11*a13);
  a00=(a09*a00);
  a15=(a00*a02);
  a15=(a15+a07);
  a07=arg[4]? arg[4][1] : 0;
  a16=(a15*a07);
  a14=(a14+a16);
  a16=(a01*a06);
  a05=(a05*a02);
  a16=(a16+a05);
  a17=arg[4]? arg[4][2] : 0;
  a18=(a16*a17);
  a14=(a14+a18);
  a18=casadi_sq(a14);
  a19=(a03*a13);
  a20=casadi_sq(a04);
  a09=(a09*a20);
  a08=(a08+a09);
  a12=(a08+a12);
  a09=(a12*a07);
  a19=(a19+a09);
  a09=(a00*a04);
  a20=(2.*a06);
  a20=(a20*a02);
  a09=(a09+a20);
  a02=(a09*a17);
  a19=(a19+a02);
  a02=casadi_sq(a19);
  a18=(a18+a02);
  a02=-5.0000000000000000e-01;
  a18=pow(a18,a02);
  a21=(a14*a18);
  a22=(a03*a21);
  a23=(a19*a18);
  a24=(a11*a23);
  a22=(a22-a24);
  if (res[0]!=0) res[0][0]=a22;
  a22=arg[2]? arg[2][47] : 0;
  a24=(a22*a11);
  a25=arg[2]? arg[2][48] : 0;
  a26=(a25*a15);
  a24=(a24+a26);
  a26=arg[2]? arg[2][49] : 0;
  a27=(a26*a16);
  a24=(a24+a27);
  a27=arg[2]? arg[2][38] : 0;
  a28=arg[4]? arg[4][3] : 0;
  a29=(a27*a28);
  a30=arg[2]? arg[2][39] : 0;
  a31=arg[4]? arg[4][4] : 0;
  a32=(a30*a31);
  a29=(a29+a32);
  a32=arg[2]? arg[2][40] : 0;
  a33=arg[4]? arg[4][5] : 0;
  a34=(a32*a33);
  a29=(a29+a34);
  a34=(a24*a29);
  a35=arg[2]? arg[2][41] : 0;
  a36=(a35*a11);
  a37=arg[2]? arg[2][42] : 0;
  a38=(a37*a15);
  a36=(a36+a38);
  a38=arg[2]? arg[2][43] : 0;
  a39=(a38*a16);
  a36=(a36+a39);
  a39=arg[0]? arg[0][7] : 0;
  a40=cos(a39);
  a41=(a36*a40);
  a42=arg[2]? arg[2][44] : 0;
  a43=(a42*a11);
  a44=arg[2]? arg[2][45] : 0;
  a45=(a44*a15);
  a43=(a43+a45);
  a45=arg[2]? arg[2][46] : 0;
  a46=(a45*a16);
  a43=(a43+a46);
  a39=sin(a39);
  a46=(a43*a39);
  a41=(a41+a46);
  a46=arg[2]? arg[2][32] : 0;
  a47=(a46*a28);
  a48=arg[2]? arg[2][33] : 0;
  a49=(a48*a31);
  a47=(a47+a49);
  a49=arg[2]? arg[2][34] : 0;
  a50=(a49*a33);
  a47=(a47+a50);
  a50=(a41*a47);
  a34=(a34+a50);
  a43=(a43*a40);
  a36=(a36*a39);
  a43=(a43-a36);
  a36=arg[2]? arg[2][35] : 0;
  a28=(a36*a28);
  a50=arg[2]? arg[2][36] : 0;
  a31=(a50*a31);
  a28=(a28+a31);
  a31=arg[2]? arg[2][37] : 0;
  a33=(a31*a33);
  a28=(a28+a33);
  a33=(a43*a28);
  a34=(a34+a33);
  a33=casadi_sq(a34);
  a51=(a22*a03);
  a52=(a25*a12);
  a51=(a51+a52);
  a52=(a26*a09);
  a51=(a51+a52);
  a52=(a51*a29);
  a53=(a35*a03);
  a54=(a37*a12);
  a53=(a53+a54);
  a54=(a38*a09);
  a53=(a53+a54);
  a54=(a53*a40);
  a55=(a42*a03);
  a56=(a44*a12);
  a55=(a55+a56);
  a56=(a45*a09);
  a55=(a55+a56);
  a56=(a55*a39);
  a54=(a54+a56);
  a56=(a54*a47);
  a52=(a52+a56);
  a55=(a55*a40);
  a53=(a53*a39);
  a55=(a55-a53);
  a53=(a55*a28);
  a52=(a52+a53);
  a53=casadi_sq(a52);
  a33=(a33+a53);
  a33=pow(a33,a02);
  a02=(a34*a33);
  a53=(a03*a02);
  a56=(a52*a33);
  a57=(a11*a56);
  a53=(a53-a57);
  if (res[0]!=0) res[0][1]=a53;
  a53=(a12*a21);
  a57=(a15*a23);
  a53=(a53-a57);
  if (res[0]!=0) res[0][2]=a53;
  a53=(a12*a02);
  a57=(a15*a56);
  a53=(a53-a57);
  if (res[0]!=0) res[0][3]=a53;
  a53=(a09*a21);
  a57=(a16*a23);
  a53=(a53-a57);
  if (res[0]!=0) res[0][4]=a53;
  a53=(a09*a02);
  a57=(a16*a56);
  a53=(a53-a57);
  if (res[0]!=0) res[0][5]=a53;
  a00=(a00*a06);
  a00=(a00+a05);
  a05=arg[3]? arg[3][0] : 0;
  a06=(a11*a05);
  a53=arg[3]? arg[3][1] : 0;
  a57=(a15*a53);
  a06=(a06+a57);
  a57=arg[3]? arg[3][2] : 0;
  a58=(a16*a57);
  a06=(a06+a58);
  a58=(a00*a06);
  a59=(a00*a05);
  a01=(a01*a04);
  a01=(a01+a20);
  a20=(a01*a53);
  a59=(a59+a20);
  a08=(a08+a10);
  a10=(a08*a57);
  a59=(a59+a10);
  a10=(a11*a59);
  a58=(a58-a10);
  a58=(a21*a58);
  a10=(a03*a59);
  a05=(a03*a05);
  a53=(a12*a53);
  a05=(a05+a53);
  a57=(a09*a57);
  a05=(a05+a57);
  a57=(a00*a05);
  a10=(a10-a57);
  a10=(a23*a10);
  a58=(a58-a10);
  if (res[0]!=0) res[0][6]=a58;
  a58=arg[2]? arg[2][50] : 0;
  a10=(a11*a58);
  a57=arg[2]? arg[2][51] : 0;
  a53=(a15*a57);
  a10=(a10+a53);
  a53=arg[2]? arg[2][52] : 0;
  a20=(a16*a53);
  a10=(a10+a20);
  a20=arg[0]? arg[0][0] : 0;
  a04=(a10+a20);
  a60=arg[3]? arg[3][3] : 0;
  a27=(a27*a60);
  a61=arg[3]? arg[3][4] : 0;
  a30=(a30*a61);
  a27=(a27+a30);
  a30=arg[3]? arg[3][5] : 0;
  a32=(a32*a30);
  a27=(a27+a32);
  a32=(a24*a27);
  a46=(a46*a60);
  a48=(a48*a61);
  a46=(a46+a48);
  a49=(a49*a30);
  a46=(a46+a49);
  a41=(a41*a46);
  a32=(a32+a41);
  a36=(a36*a60);
  a50=(a50*a61);
  a36=(a36+a50);
  a31=(a31*a30);
  a36=(a36+a31);
  a43=(a43*a36);
  a32=(a32+a43);
  a04=(a04+a32);
  a04=(a04-a20);
  a20=(a00*a04);
  a43=(a00*a58);
  a31=(a01*a57);
  a43=(a43+a31);
  a31=(a08*a53);
  a43=(a43+a31);
  a31=arg[0]? arg[0][2] : 0;
  a30=(a43+a31);
  a22=(a22*a00);
  a25=(a25*a01);
  a22=(a22+a25);
  a26=(a26*a08);
  a22=(a22+a26);
  a26=(a22*a27);
  a35=(a35*a00);
  a37=(a37*a01);
  a35=(a35+a37);
  a38=(a38*a08);
  a35=(a35+a38);
  a38=(a35*a40);
  a42=(a42*a00);
  a44=(a44*a01);
  a42=(a42+a44);
  a45=(a45*a08);
  a42=(a42+a45);
  a45=(a42*a39);
  a38=(a38+a45);
  a45=(a38*a46);
  a26=(a26+a45);
  a42=(a42*a40);
  a35=(a35*a39);
  a42=(a42-a35);
  a35=(a42*a36);
  a26=(a26+a35);
  a30=(a30+a26);
  a30=(a30-a31);
  a31=(a11*a30);
  a20=(a20-a31);
  a20=(a02*a20);
  a31=(a03*a30);
  a58=(a03*a58);
  a57=(a12*a57);
  a58=(a58+a57);
  a53=(a09*a53);
  a58=(a58+a53);
  a53=arg[0]? arg[0][1] : 0;
  a57=(a58+a53);
  a27=(a51*a27);
  a54=(a54*a46);
  a27=(a27+a54);
  a55=(a55*a36);
  a27=(a27+a55);
  a57=(a57+a27);
  a57=(a57-a53);
  a53=(a00*a57);
  a31=(a31-a53);
  a31=(a56*a31);
  a20=(a20-a31);
  if (res[0]!=0) res[0][7]=a20;
  a20=(a01*a06);
  a31=(a15*a59);
  a20=(a20-a31);
  a20=(a21*a20);
  a31=(a12*a59);
  a53=(a01*a05);
  a31=(a31-a53);
  a31=(a23*a31);
  a20=(a20-a31);
  if (res[0]!=0) res[0][8]=a20;
  a20=(a01*a04);
  a31=(a15*a30);
  a20=(a20-a31);
  a20=(a02*a20);
  a31=(a12*a30);
  a53=(a01*a57);
  a31=(a31-a53);
  a31=(a56*a31);
  a20=(a20-a31);
  if (res[0]!=0) res[0][9]=a20;
  a20=(a08*a06);
  a31=(a16*a59);
  a20=(a20-a31);
  a20=(a21*a20);
  a31=(a09*a59);
  a53=(a08*a05);
  a31=(a31-a53);
  a31=(a23*a31);
  a20=(a20-a31);
  if (res[0]!=0) res[0][10]=a20;
  a04=(a08*a04);
  a20=(a16*a30);
  a04=(a04-a20);
  a04=(a02*a04);
  a30=(a09*a30);
  a57=(a08*a57);
  a30=(a30-a57);
  a30=(a56*a30);
  a04=(a04-a30);
  if (res[0]!=0) res[0][11]=a04;
  a04=0.;
  if (res[0]!=0) res[0][12]=a04;
  a04=(a22*a32);
  a30=(a24*a26);
  a04=(a04-a30);
  a04=(a02*a04);
  a30=(a51*a26);
  a57=(a22*a27);
  a30=(a30-a57);
  a30=(a56*a30);
  a04=(a04-a30);
  if (res[0]!=0) res[0][13]=a04;
  a04=arg[1]? arg[1][3] : 0;
  a30=(a00*a04);
  a57=arg[1]? arg[1][4] : 0;
  a20=(a01*a57);
  a30=(a30+a20);
  a20=arg[1]? arg[1][5] : 0;
  a31=(a08*a20);
  a30=(a30+a31);
  a31=arg[1]? arg[1][0] : 0;
  a53=(a11*a31);
  a55=arg[1]? arg[1][1] : 0;
  a36=(a15*a55);
  a53=(a53+a36);
  a36=arg[1]? arg[1][2] : 0;
  a54=(a16*a36);
  a53=(a53+a54);
  a54=(a30*a53);
  a11=(a11*a04);
  a15=(a15*a57);
  a11=(a11+a15);
  a16=(a16*a20);
  a11=(a11+a16);
  a16=(a00*a31);
  a15=(a01*a55);
  a16=(a16+a15);
  a15=(a08*a36);
  a16=(a16+a15);
  a15=(a11*a16);
  a54=(a54-a15);
  a04=(a03*a04);
  a57=(a12*a57);
  a04=(a04+a57);
  a20=(a09*a20);
  a04=(a04+a20);
  a20=(a04*a59);
  a57=(a30*a05);
  a15=(a20-a57);
  a15=(a30*a15);
  a15=(a54+a15);
  a05=(a11*a05);
  a46=(a04*a06);
  a05=(a05-a46);
  a46=(a11*a05);
  a15=(a15-a46);
  a15=(a15*a21);
  a16=(a04*a16);
  a03=(a03*a31);
  a12=(a12*a55);
  a03=(a03+a12);
  a09=(a09*a36);
  a03=(a03+a09);
  a09=(a30*a03);
  a16=(a16-a09);
  a05=(a04*a05);
  a05=(a16+a05);
  a06=(a30*a06);
  a59=(a11*a59);
  a09=(a06-a59);
  a09=(a30*a09);
  a05=(a05-a09);
  a05=(a05*a23);
  a15=(a15-a05);
  a20=(a53+a20);
  a20=(a20-a57);
  a20=(a20*a18);
  a00=(a00*a13);
  a01=(a01*a07);
  a00=(a00+a01);
  a08=(a08*a17);
  a00=(a00+a08);
  a08=(a04*a00);
  a19=(a30*a19);
  a08=(a08-a19);
  a19=(a08*a21);
  a14=(a30*a14);
  a00=(a11*a00);
  a14=(a14-a00);
  a00=(a14*a23);
  a19=(a19+a00);
  a23=(a19*a23);
  a23=(a23-a14);
  a20=(a20*a23);
  a15=(a15+a20);
  a06=(a03+a06);
  a06=(a06-a59);
  a06=(a06*a18);
  a19=(a19*a21);
  a08=(a08-a19);
  a06=(a06*a08);
  a15=(a15+a06);
  if (res[1]!=0) res[1][0]=a15;
  a15=(a43*a04);
  a06=(a58*a30);
  a08=(a15-a06);
  a08=(a30*a08);
  a54=(a54+a08);
  a58=(a58*a11);
  a08=(a10*a04);
  a58=(a58-a08);
  a08=(a11*a58);
  a54=(a54-a08);
  a08=arg[1]? arg[1][6] : 0;
  a19=(a51*a11);
  a21=(a24*a04);
  a19=(a19-a21);
  a19=(a08*a19);
  a21=(a19*a32);
  a54=(a54+a21);
  a21=(a22*a08);
  a21=(a30+a21);
  a18=(a51*a08);
  a18=(a04+a18);
  a59=(a18*a26);
  a20=(a21*a27);
  a23=(a59-a20);
  a23=(a21*a23);
  a54=(a54+a23);
  a23=(a22*a04);
  a51=(a51*a30);
  a23=(a23-a51);
  a23=(a08*a23);
  a23=(a23*a26);
  a54=(a54-a23);
  a23=(a24*a08);
  a23=(a11+a23);
  a51=(a23*a27);
  a14=(a18*a32);
  a51=(a51-a14);
  a14=(a23*a51);
  a54=(a54-a14);
  a54=(a54*a02);
  a04=(a04*a58);
  a16=(a16+a04);
  a10=(a10*a30);
  a43=(a43*a11);
  a04=(a10-a43);
  a04=(a30*a04);
  a16=(a16-a04);
  a24=(a24*a30);
  a11=(a22*a11);
  a24=(a24-a11);
  a08=(a08*a24);
  a08=(a08*a26);
  a16=(a16+a08);
  a51=(a18*a51);
  a16=(a16+a51);
  a19=(a19*a27);
  a16=(a16-a19);
  a32=(a21*a32);
  a26=(a23*a26);
  a19=(a32-a26);
  a19=(a21*a19);
  a16=(a16-a19);
  a16=(a16*a56);
  a54=(a54-a16);
  a53=(a53+a15);
  a53=(a53-a06);
  a53=(a53+a59);
  a53=(a53-a20);
  a53=(a53*a33);
  a22=(a22*a29);
  a38=(a38*a47);
  a22=(a22+a38);
  a42=(a42*a28);
  a22=(a22+a42);
  a18=(a18*a22);
  a52=(a21*a52);
  a18=(a18-a52);
  a52=(a18*a02);
  a21=(a21*a34);
  a23=(a23*a22);
  a21=(a21-a23);
  a23=(a21*a56);
  a52=(a52+a23);
  a56=(a52*a56);
  a56=(a56-a21);
  a53=(a53*a56);
  a54=(a54+a53);
  a03=(a03+a10);
  a03=(a03-a43);
  a03=(a03+a32);
  a03=(a03-a26);
  a03=(a03*a33);
  a52=(a52*a02);
  a18=(a18-a52);
  a03=(a03*a18);
  a54=(a54+a03);
  if (res[1]!=0) res[1][1]=a54;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_wheel_rows_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_wheel_rows_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_wheel_rows_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_wheel_rows_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_wheel_rows_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_wheel_rows_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_wheel_rows_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "wheel_points";
    case 4: return "wheel_heading";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_wheel_rows_name_out(casadi_int i) {
  switch (i) {
    case 0: return "A";
    case 1: return "adot_v";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_wheel_rows_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_wheel_rows_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_wheel_rows_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_wheel_rows(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[5];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 63);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 5; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    r[0] = res[0] + i * 14;
    r[1] = res[1] + i * 2;
    if (snakecg_sp1_wheel_rows(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
