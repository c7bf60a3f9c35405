/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system_at_rest() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 1ffd02983b32fea1953b31d6b4da6e985de5a598f8e69763f0a5d6374958d5e8
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_contact_system_at_rest_ ## ID
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
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
#define casadi_s9 CASADI_PREFIX(s9)
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
CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_at_rest_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {2, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {25, 1, 1};
static const casadi_int casadi_s4[3] = {1, 1, 1};
static const casadi_int casadi_s5[3] = {5, 5, 1};
static const casadi_int casadi_s6[3] = {4, 4, 1};
static const casadi_int casadi_s7[3] = {4, 1, 1};
static const casadi_int casadi_s8[3] = {5, 4, 1};
static const casadi_int casadi_s9[3] = {3, 4, 1};

/* snakecg_na2_contact_system_at_rest:(q[5],tau[2],q_obj[3],f_obj[3],K[25],contact_link[3],side,object_mass,object_inertia,rho[2],wheel_offset[3],contact_offset,object_distance,placed)->(M[5x5],delassus[4x4],b[4],qdd_free[5],a_obj_free[3],qdd_from_lam[5x4],a_obj_from_lam[3x4],gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63;
  a00=arg[4]? arg[4][12] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[4]? arg[4][15] : 0;
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a03=sin(a03);
  a05=sin(a05);
  a08=(a03*a05);
  a07=(a07-a08);
  a08=arg[0]? arg[0][4] : 0;
  a09=sin(a08);
  a10=(a07*a09);
  a08=cos(a08);
  a05=(a04*a05);
  a11=(a06*a03);
  a11=(a05+a11);
  a12=(a08*a11);
  a12=(a10+a12);
  a13=(a02*a12);
  a14=arg[4]? arg[4][14] : 0;
  a15=(a14*a11);
  a15=(a13+a15);
  a16=arg[4]? arg[4][13] : 0;
  a17=(a16*a03);
  a17=(a15+a17);
  a18=(-a17);
  if (res[0]!=0) res[0][2]=a18;
  a19=(-a15);
  if (res[0]!=0) res[0][3]=a19;
  a20=(-a13);
  if (res[0]!=0) res[0][4]=a20;
  if (res[0]!=0) res[0][5]=a01;
  if (res[0]!=0) res[0][6]=a00;
  a21=(a07*a08);
  a22=(a11*a09);
  a22=(a21-a22);
  a02=(a02*a22);
  a14=(a14*a07);
  a14=(a02+a14);
  a16=(a16*a04);
  a16=(a14+a16);
  if (res[0]!=0) res[0][7]=a16;
  if (res[0]!=0) res[0][8]=a14;
  if (res[0]!=0) res[0][9]=a02;
  if (res[0]!=0) res[0][10]=a18;
  if (res[0]!=0) res[0][11]=a16;
  a18=arg[4]? arg[4][4] : 0;
  a23=(a07*a18);
  a23=(a02*a23);
  a24=(a11*a18);
  a24=(a13*a24);
  a23=(a23+a24);
  a24=arg[4]? arg[4][24] : 0;
  a25=(a23+a24);
  a23=(a25+a23);
  a26=arg[4]? arg[4][23] : 0;
  a23=(a23+a26);
  a26=arg[4]? arg[4][3] : 0;
  a27=arg[4]? arg[4][9] : 0;
  a26=(a26-a27);
  a28=(a04*a26);
  a29=(a14*a28);
  a26=(a26*a03);
  a30=(a15*a26);
  a29=(a29+a30);
  a30=(a23+a29);
  a29=(a30+a29);
  a31=arg[4]? arg[4][22] : 0;
  a29=(a29+a31);
  if (res[0]!=0) res[0][12]=a29;
  if (res[0]!=0) res[0][13]=a30;
  a31=(a02*a28);
  a32=(a13*a26);
  a31=(a31+a32);
  a31=(a25+a31);
  if (res[0]!=0) res[0][14]=a31;
  if (res[0]!=0) res[0][15]=a19;
  if (res[0]!=0) res[0][16]=a14;
  if (res[0]!=0) res[0][17]=a30;
  if (res[0]!=0) res[0][18]=a23;
  if (res[0]!=0) res[0][19]=a25;
  if (res[0]!=0) res[0][20]=a20;
  if (res[0]!=0) res[0][21]=a02;
  if (res[0]!=0) res[0][22]=a31;
  if (res[0]!=0) res[0][23]=a25;
  if (res[0]!=0) res[0][24]=a24;
  a20=arg[5]? arg[5][0] : 0;
  a19=(a20*a03);
  a32=arg[5]? arg[5][1] : 0;
  a06=(a03*a06);
  a06=(a06+a05);
  a05=(a32*a06);
  a19=(a19+a05);
  a05=arg[5]? arg[5][2] : 0;
  a08=(a06*a08);
  a08=(a08+a10);
  a10=(a05*a08);
  a19=(a19+a10);
  a10=arg[6]? arg[6][0] : 0;
  a33=(a19*a10);
  a34=(a20+a32);
  a34=(a34+a05);
  a35=(a33*a34);
  a36=(a35/a00);
  a17=(a17/a00);
  a37=arg[0]? arg[0][1] : 0;
  a26=(a37+a26);
  a38=arg[4]? arg[4][10] : 0;
  a39=(a11*a38);
  a40=(a26+a39);
  a41=(a37-a40);
  a42=(a32*a41);
  a18=(a18-a38);
  a11=(a18*a11);
  a11=(a40+a11);
  a43=arg[4]? arg[4][11] : 0;
  a12=(a12*a43);
  a11=(a11+a12);
  a44=(a37-a11);
  a45=(a05*a44);
  a42=(a42+a45);
  a42=(a33*a42);
  a45=(a20*a04);
  a46=(a32*a07);
  a45=(a45+a46);
  a09=(a06*a09);
  a21=(a21-a09);
  a09=(a05*a21);
  a45=(a45+a09);
  a09=(a45*a10);
  a46=arg[0]? arg[0][0] : 0;
  a28=(a46+a28);
  a47=(a07*a38);
  a48=(a28+a47);
  a49=(a48-a46);
  a50=(a32*a49);
  a18=(a07*a18);
  a18=(a48+a18);
  a22=(a22*a43);
  a18=(a18+a22);
  a51=(a18-a46);
  a52=(a05*a51);
  a50=(a50+a52);
  a50=(a09*a50);
  a42=(a42-a50);
  a27=(a27*a20);
  a38=(a38*a32);
  a27=(a27+a38);
  a43=(a43*a05);
  a27=(a27+a43);
  a43=(a10*a27);
  a38=casadi_sq(a19);
  a38=(a43*a38);
  a50=casadi_sq(a45);
  a43=(a43*a50);
  a38=(a38+a43);
  a43=1.;
  a50=arg[13]? arg[13][0] : 0;
  a43=(a43-a50);
  a52=arg[2]? arg[2][2] : 0;
  a53=cos(a52);
  a53=(a43*a53);
  a54=(a50*a45);
  a53=(a53+a54);
  a54=arg[9]? arg[9][1] : 0;
  a54=(a43*a54);
  a55=arg[12]? arg[12][0] : 0;
  a56=(a10*a55);
  a56=(a50*a56);
  a54=(a54-a56);
  a56=(a53*a54);
  a52=sin(a52);
  a52=(a43*a52);
  a57=(a50*a19);
  a52=(a52+a57);
  a57=arg[9]? arg[9][0] : 0;
  a57=(a43*a57);
  a58=(a52*a57);
  a56=(a56+a58);
  a58=arg[2]? arg[2][1] : 0;
  a58=(a43*a58);
  a37=(a37*a20);
  a40=(a40*a32);
  a37=(a37+a40);
  a40=(a11*a05);
  a37=(a37+a40);
  a40=arg[11]? arg[11][0] : 0;
  a40=(a40-a27);
  a59=(a40*a19);
  a59=(a37+a59);
  a60=(a10*a45);
  a60=(a55*a60);
  a59=(a59+a60);
  a59=(a50*a59);
  a58=(a58+a59);
  a58=(a56+a58);
  a59=(a19*a27);
  a58=(a58+a59);
  a58=(a58-a37);
  a37=(a33*a58);
  a38=(a38-a37);
  a53=(a53*a57);
  a52=(a52*a54);
  a53=(a53-a52);
  a52=arg[2]? arg[2][0] : 0;
  a43=(a43*a52);
  a46=(a46*a20);
  a48=(a48*a32);
  a46=(a46+a48);
  a48=(a18*a05);
  a46=(a46+a48);
  a40=(a40*a45);
  a40=(a46+a40);
  a48=(a10*a19);
  a55=(a55*a48);
  a40=(a40-a55);
  a50=(a50*a40);
  a43=(a43+a50);
  a43=(a53+a43);
  a27=(a45*a27);
  a43=(a43+a27);
  a43=(a43-a46);
  a46=(a09*a43);
  a38=(a38-a46);
  a46=(a38*a34);
  a42=(a42+a46);
  a46=(a17*a35);
  a46=(a42+a46);
  a16=(a16/a00);
  a34=(a09*a34);
  a27=(a16*a34);
  a46=(a46+a27);
  a27=casadi_sq(a17);
  a27=(a27*a00);
  a29=(a29-a27);
  a27=casadi_sq(a16);
  a27=(a27*a00);
  a29=(a29-a27);
  a27=(a46/a29);
  a15=(a15/a00);
  a50=(a15*a17);
  a50=(a50*a00);
  a30=(a30-a50);
  a14=(a14/a00);
  a50=(a14*a16);
  a50=(a50*a00);
  a30=(a30-a50);
  a30=(a30/a29);
  a26=(a26-a11);
  a11=(a05*a26);
  a50=(a32*a39);
  a11=(a11-a50);
  a11=(a33*a11);
  a50=(a32*a47);
  a18=(a18-a28);
  a28=(a05*a18);
  a50=(a50+a28);
  a50=(a09*a50);
  a11=(a11-a50);
  a32=(a32+a05);
  a32=(a38*a32);
  a11=(a11+a32);
  a32=(a15*a35);
  a32=(a11+a32);
  a50=(a14*a34);
  a32=(a32+a50);
  a50=(a30*a46);
  a32=(a32-a50);
  a50=casadi_sq(a15);
  a50=(a50*a00);
  a23=(a23-a50);
  a50=casadi_sq(a14);
  a50=(a50*a00);
  a23=(a23-a50);
  a50=casadi_sq(a30);
  a50=(a50*a29);
  a23=(a23-a50);
  a50=(a32/a23);
  a13=(a13/a00);
  a28=(a13*a15);
  a28=(a28*a00);
  a25=(a25-a28);
  a02=(a02/a00);
  a28=(a02*a14);
  a28=(a28*a00);
  a25=(a25-a28);
  a28=(a13*a17);
  a28=(a28*a00);
  a31=(a31-a28);
  a28=(a02*a16);
  a28=(a28*a00);
  a31=(a31-a28);
  a31=(a31/a29);
  a28=(a31*a30);
  a28=(a28*a29);
  a25=(a25-a28);
  a25=(a25/a23);
  a38=(a38*a05);
  a28=(a05*a12);
  a28=(a33*a28);
  a05=(a05*a22);
  a05=(a09*a05);
  a28=(a28+a05);
  a38=(a38-a28);
  a28=(a13*a35);
  a28=(a38+a28);
  a05=(a02*a34);
  a28=(a28+a05);
  a46=(a31*a46);
  a28=(a28-a46);
  a32=(a25*a32);
  a28=(a28-a32);
  a32=casadi_sq(a13);
  a32=(a32*a00);
  a24=(a24-a32);
  a32=casadi_sq(a02);
  a32=(a32*a00);
  a24=(a24-a32);
  a32=casadi_sq(a31);
  a32=(a32*a29);
  a24=(a24-a32);
  a32=casadi_sq(a25);
  a32=(a32*a23);
  a24=(a24-a32);
  a28=(a28/a24);
  a32=(a25*a28);
  a50=(a50-a32);
  a32=(a30*a50);
  a27=(a27-a32);
  a32=(a31*a28);
  a27=(a27-a32);
  a32=(a17*a27);
  a36=(a36+a32);
  a32=(a15*a50);
  a36=(a36+a32);
  a32=(a13*a28);
  a36=(a36+a32);
  a32=(a35*a36);
  a46=(a34/a00);
  a05=(a16*a27);
  a46=(a46+a05);
  a05=(a14*a50);
  a46=(a46+a05);
  a05=(a02*a28);
  a46=(a46+a05);
  a05=(a34*a46);
  a32=(a32+a05);
  a05=(a42*a27);
  a32=(a32+a05);
  a05=(a11*a50);
  a32=(a32+a05);
  a05=(a38*a28);
  a32=(a32+a05);
  a05=arg[7]? arg[7][0] : 0;
  a40=(a33/a05);
  a55=(a33*a40);
  a48=(a09/a05);
  a20=(a09*a48);
  a55=(a55+a20);
  a53=(a45*a53);
  a53=(a53*a10);
  a56=(a33*a56);
  a53=(a53+a56);
  a56=arg[8]? arg[8][0] : 0;
  a20=(a53/a56);
  a52=(a53*a20);
  a55=(a55+a52);
  a32=(a32+a55);
  if (res[1]!=0) res[1][0]=a32;
  a32=arg[10]? arg[10][0] : 0;
  a55=(a32*a27);
  a52=(a03*a36);
  a54=(a04*a46);
  a52=(a52+a54);
  a55=(a55-a52);
  if (res[1]!=0) res[1][1]=a55;
  a49=(a07*a49);
  a41=(a06*a41);
  a49=(a49-a41);
  a41=arg[10]? arg[10][1] : 0;
  a49=(a49+a41);
  a55=(a49*a27);
  a52=(a06*a36);
  a54=(a07*a46);
  a52=(a52+a54);
  a55=(a55-a52);
  a39=(a06*a39);
  a47=(a07*a47);
  a39=(a39+a47);
  a39=(a39+a41);
  a41=(a39*a50);
  a55=(a55+a41);
  if (res[1]!=0) res[1][2]=a55;
  a51=(a21*a51);
  a44=(a08*a44);
  a51=(a51-a44);
  a44=arg[10]? arg[10][2] : 0;
  a51=(a51+a44);
  a55=(a51*a27);
  a41=(a08*a36);
  a47=(a21*a46);
  a41=(a41+a47);
  a55=(a55-a41);
  a18=(a21*a18);
  a26=(a08*a26);
  a18=(a18-a26);
  a18=(a18+a44);
  a26=(a18*a50);
  a55=(a55+a26);
  a12=(a08*a12);
  a22=(a21*a22);
  a12=(a12+a22);
  a12=(a12+a44);
  a44=(a12*a28);
  a55=(a55+a44);
  if (res[1]!=0) res[1][3]=a55;
  a55=(a17*a03);
  a55=(a32-a55);
  a44=(a16*a04);
  a55=(a55-a44);
  a44=(a55/a29);
  a22=(a15*a03);
  a26=(a14*a04);
  a22=(a22+a26);
  a26=(a30*a55);
  a22=(a22+a26);
  a26=(a22/a23);
  a22=(a25*a22);
  a41=(a13*a03);
  a47=(a02*a04);
  a41=(a41+a47);
  a55=(a31*a55);
  a41=(a41+a55);
  a22=(a22-a41);
  a22=(a22/a24);
  a41=(a25*a22);
  a26=(a26+a41);
  a41=(a30*a26);
  a44=(a44+a41);
  a41=(a31*a22);
  a44=(a44-a41);
  a41=(a17*a44);
  a55=(a03/a00);
  a41=(a41-a55);
  a55=(a15*a26);
  a41=(a41-a55);
  a55=(a13*a22);
  a41=(a41+a55);
  a55=(a35*a41);
  a47=(a04/a00);
  a52=(a16*a44);
  a47=(a47-a52);
  a52=(a14*a26);
  a47=(a47+a52);
  a52=(a02*a22);
  a47=(a47-a52);
  a52=(a34*a47);
  a55=(a55-a52);
  a52=(a42*a44);
  a55=(a55+a52);
  a52=(a11*a26);
  a55=(a55-a52);
  a52=(a38*a22);
  a55=(a55+a52);
  if (res[1]!=0) res[1][4]=a55;
  a55=(a04*a47);
  a52=(a03*a41);
  a55=(a55-a52);
  a52=(a32*a44);
  a55=(a55+a52);
  if (res[1]!=0) res[1][5]=a55;
  a55=(a07*a47);
  a52=(a06*a41);
  a55=(a55-a52);
  a52=(a49*a44);
  a55=(a55+a52);
  a52=(a39*a26);
  a55=(a55-a52);
  if (res[1]!=0) res[1][6]=a55;
  a55=(a21*a47);
  a52=(a08*a41);
  a55=(a55-a52);
  a52=(a51*a44);
  a55=(a55+a52);
  a52=(a18*a26);
  a55=(a55-a52);
  a52=(a12*a22);
  a55=(a55+a52);
  if (res[1]!=0) res[1][7]=a55;
  a55=(a17*a06);
  a55=(a49-a55);
  a52=(a16*a07);
  a55=(a55-a52);
  a52=(a55/a29);
  a54=(a15*a06);
  a54=(a39-a54);
  a57=(a14*a07);
  a54=(a54-a57);
  a57=(a30*a55);
  a54=(a54-a57);
  a57=(a54/a23);
  a37=(a13*a06);
  a59=(a02*a07);
  a37=(a37+a59);
  a55=(a31*a55);
  a37=(a37+a55);
  a54=(a25*a54);
  a37=(a37+a54);
  a37=(a37/a24);
  a54=(a25*a37);
  a57=(a57+a54);
  a54=(a30*a57);
  a52=(a52-a54);
  a54=(a31*a37);
  a52=(a52+a54);
  a54=(a17*a52);
  a55=(a06/a00);
  a54=(a54-a55);
  a55=(a15*a57);
  a54=(a54+a55);
  a55=(a13*a37);
  a54=(a54-a55);
  a55=(a35*a54);
  a59=(a07/a00);
  a60=(a16*a52);
  a59=(a59-a60);
  a60=(a14*a57);
  a59=(a59-a60);
  a60=(a02*a37);
  a59=(a59+a60);
  a60=(a34*a59);
  a55=(a55-a60);
  a60=(a42*a52);
  a55=(a55+a60);
  a60=(a11*a57);
  a55=(a55+a60);
  a60=(a38*a37);
  a55=(a55-a60);
  if (res[1]!=0) res[1][8]=a55;
  a55=(a04*a59);
  a60=(a03*a54);
  a55=(a55-a60);
  a60=(a32*a52);
  a55=(a55+a60);
  if (res[1]!=0) res[1][9]=a55;
  a55=(a07*a59);
  a60=(a06*a54);
  a55=(a55-a60);
  a60=(a49*a52);
  a55=(a55+a60);
  a60=(a39*a57);
  a55=(a55+a60);
  if (res[1]!=0) res[1][10]=a55;
  a55=(a21*a59);
  a60=(a08*a54);
  a55=(a55-a60);
  a60=(a51*a52);
  a55=(a55+a60);
  a60=(a18*a57);
  a55=(a55+a60);
  a60=(a12*a37);
  a55=(a55-a60);
  if (res[1]!=0) res[1][11]=a55;
  a55=(a17*a08);
  a55=(a51-a55);
  a60=(a16*a21);
  a55=(a55-a60);
  a29=(a55/a29);
  a60=(a15*a08);
  a60=(a18-a60);
  a61=(a14*a21);
  a60=(a60-a61);
  a61=(a30*a55);
  a60=(a60-a61);
  a61=(a60/a23);
  a62=(a13*a08);
  a62=(a12-a62);
  a63=(a02*a21);
  a62=(a62-a63);
  a55=(a31*a55);
  a62=(a62-a55);
  a60=(a25*a60);
  a62=(a62-a60);
  a62=(a62/a24);
  a60=(a25*a62);
  a61=(a61-a60);
  a60=(a30*a61);
  a29=(a29-a60);
  a60=(a31*a62);
  a29=(a29-a60);
  a60=(a17*a29);
  a55=(a08/a00);
  a60=(a60-a55);
  a55=(a15*a61);
  a60=(a60+a55);
  a55=(a13*a62);
  a60=(a60+a55);
  a55=(a35*a60);
  a00=(a21/a00);
  a63=(a16*a29);
  a00=(a00-a63);
  a63=(a14*a61);
  a00=(a00-a63);
  a63=(a02*a62);
  a00=(a00-a63);
  a63=(a34*a00);
  a55=(a55-a63);
  a63=(a42*a29);
  a55=(a55+a63);
  a63=(a11*a61);
  a55=(a55+a63);
  a63=(a38*a62);
  a55=(a55+a63);
  if (res[1]!=0) res[1][12]=a55;
  a55=(a04*a00);
  a63=(a03*a60);
  a55=(a55-a63);
  a63=(a32*a29);
  a55=(a55+a63);
  if (res[1]!=0) res[1][13]=a55;
  a55=(a07*a00);
  a63=(a06*a60);
  a55=(a55-a63);
  a63=(a49*a29);
  a55=(a55+a63);
  a63=(a39*a61);
  a55=(a55+a63);
  if (res[1]!=0) res[1][14]=a55;
  a55=(a21*a00);
  a63=(a08*a60);
  a55=(a55-a63);
  a63=(a51*a29);
  a55=(a55+a63);
  a63=(a18*a61);
  a55=(a55+a63);
  a63=(a12*a62);
  a55=(a55+a63);
  if (res[1]!=0) res[1][15]=a55;
  a55=arg[1]? arg[1][0] : 0;
  a23=(a55/a23);
  a63=arg[1]? arg[1][1] : 0;
  a55=(a25*a55);
  a63=(a63-a55);
  a63=(a63/a24);
  a25=(a25*a63);
  a23=(a23-a25);
  a15=(a15*a23);
  a30=(a30*a23);
  a31=(a31*a63);
  a30=(a30+a31);
  a17=(a17*a30);
  a15=(a15-a17);
  a13=(a13*a63);
  a15=(a15+a13);
  a35=(a35*a15);
  a16=(a16*a30);
  a14=(a14*a23);
  a16=(a16-a14);
  a02=(a02*a63);
  a16=(a16-a02);
  a34=(a34*a16);
  a35=(a35-a34);
  a42=(a42*a30);
  a35=(a35-a42);
  a11=(a11*a23);
  a35=(a35+a11);
  a38=(a38*a63);
  a35=(a35+a38);
  a38=arg[3]? arg[3][1] : 0;
  a38=(a38/a05);
  a11=(a09*a38);
  a42=arg[3]? arg[3][0] : 0;
  a42=(a42/a05);
  a33=(a33*a42);
  a11=(a11-a33);
  a33=arg[3]? arg[3][2] : 0;
  a33=(a33/a56);
  a53=(a53*a33);
  a11=(a11+a53);
  a35=(a35+a11);
  if (res[2]!=0) res[2][0]=a35;
  a04=(a04*a16);
  a03=(a03*a15);
  a04=(a04-a03);
  a32=(a32*a30);
  a04=(a04-a32);
  if (res[2]!=0) res[2][1]=a04;
  a07=(a07*a16);
  a06=(a06*a15);
  a07=(a07-a06);
  a49=(a49*a30);
  a07=(a07-a49);
  a39=(a39*a23);
  a07=(a07+a39);
  if (res[2]!=0) res[2][2]=a07;
  a21=(a21*a16);
  a08=(a08*a15);
  a21=(a21-a08);
  a51=(a51*a30);
  a21=(a21-a51);
  a18=(a18*a23);
  a21=(a21+a18);
  a12=(a12*a63);
  a21=(a21+a12);
  if (res[2]!=0) res[2][3]=a21;
  if (res[3]!=0) res[3][0]=a15;
  if (res[3]!=0) res[3][1]=a16;
  a30=(-a30);
  if (res[3]!=0) res[3][2]=a30;
  if (res[3]!=0) res[3][3]=a23;
  if (res[3]!=0) res[3][4]=a63;
  if (res[4]!=0) res[4][0]=a42;
  if (res[4]!=0) res[4][1]=a38;
  if (res[4]!=0) res[4][2]=a33;
  if (res[5]!=0) res[5][0]=a36;
  a46=(-a46);
  if (res[5]!=0) res[5][1]=a46;
  if (res[5]!=0) res[5][2]=a27;
  if (res[5]!=0) res[5][3]=a50;
  if (res[5]!=0) res[5][4]=a28;
  if (res[5]!=0) res[5][5]=a41;
  if (res[5]!=0) res[5][6]=a47;
  if (res[5]!=0) res[5][7]=a44;
  a26=(-a26);
  if (res[5]!=0) res[5][8]=a26;
  if (res[5]!=0) res[5][9]=a22;
  if (res[5]!=0) res[5][10]=a54;
  if (res[5]!=0) res[5][11]=a59;
  if (res[5]!=0) res[5][12]=a52;
  if (res[5]!=0) res[5][13]=a57;
  a37=(-a37);
  if (res[5]!=0) res[5][14]=a37;
  if (res[5]!=0) res[5][15]=a60;
  if (res[5]!=0) res[5][16]=a00;
  if (res[5]!=0) res[5][17]=a29;
  if (res[5]!=0) res[5][18]=a61;
  if (res[5]!=0) res[5][19]=a62;
  a40=(-a40);
  if (res[6]!=0) res[6][0]=a40;
  if (res[6]!=0) res[6][1]=a48;
  if (res[6]!=0) res[6][2]=a20;
  if (res[6]!=0) res[6][3]=a01;
  if (res[6]!=0) res[6][4]=a01;
  if (res[6]!=0) res[6][5]=a01;
  if (res[6]!=0) res[6][6]=a01;
  if (res[6]!=0) res[6][7]=a01;
  if (res[6]!=0) res[6][8]=a01;
  if (res[6]!=0) res[6][9]=a01;
  if (res[6]!=0) res[6][10]=a01;
  if (res[6]!=0) res[6][11]=a01;
  a09=(a58*a09);
  a01=(a19*a43);
  a01=(a01*a10);
  a09=(a09-a01);
  if (res[7]!=0) res[7][0]=a09;
  a19=(a19*a58);
  a45=(a45*a43);
  a19=(a19+a45);
  if (res[8]!=0) res[8][0]=a19;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_at_rest_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_at_rest_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_at_rest_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_at_rest_n_in(void) { return 14;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_at_rest_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_contact_system_at_rest_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_at_rest_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "tau";
    case 2: return "q_obj";
    case 3: return "f_obj";
    case 4: return "K";
    case 5: return "contact_link";
    case 6: return "side";
    case 7: return "object_mass";
    case 8: return "object_inertia";
    case 9: return "rho";
    case 10: return "wheel_offset";
    case 11: return "contact_offset";
    case 12: return "object_distance";
    case 13: return "placed";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_at_rest_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    case 1: return "delassus";
    case 2: return "b";
    case 3: return "qdd_free";
    case 4: return "a_obj_free";
    case 5: return "qdd_from_lam";
    case 6: return "a_obj_from_lam";
    case 7: return "gap";
    case 8: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_at_rest_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    case 4: return casadi_s3;
    case 5: return casadi_s2;
    case 6: return casadi_s4;
    case 7: return casadi_s4;
    case 8: return casadi_s4;
    case 9: return casadi_s1;
    case 10: return casadi_s2;
    case 11: return casadi_s4;
    case 12: return casadi_s4;
    case 13: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_at_rest_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s7;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s8;
    case 6: return casadi_s9;
    case 7: return casadi_s4;
    case 8: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_at_rest_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 14*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 9*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_contact_system_at_rest(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[14];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 65);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 14; ++k) a[k] = 0;
  for (k = 0; k < 9; ++k) r[k] = 0;
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
    r[0] = res[0] + i * 25;
    r[1] = res[1] + i * 16;
    r[2] = res[2] + i * 4;
    r[3] = res[3] + i * 5;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 20;
    r[6] = res[6] + i * 12;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na2_contact_system_at_rest(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
