/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system() of
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
  #define CASADI_PREFIX(ID) snakecg_na1_contact_system_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {16, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {4, 4, 1};
static const casadi_int casadi_s6[3] = {3, 3, 1};
static const casadi_int casadi_s7[3] = {4, 3, 1};

/* snakecg_na1_contact_system:(q[4],v[4],tau,q_obj[3],v_obj[3],f_obj[3],K[16],contact_link[2],side,object_mass,object_inertia,rho[2],wheel_offset[2],contact_offset,object_distance,placed)->(M[4x4],delassus[3x3],b[3],qdd_free[4],a_obj_free[3],qdd_from_lam[4x3],a_obj_from_lam[3x3],gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74;
  a00=arg[6]? arg[6][8] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[6]? arg[6][10] : 0;
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=sin(a05);
  a07=(a04*a06);
  a05=cos(a05);
  a03=sin(a03);
  a08=(a05*a03);
  a08=(a07+a08);
  a09=(a02*a08);
  a10=arg[6]? arg[6][9] : 0;
  a11=(a10*a03);
  a11=(a09+a11);
  a12=(-a11);
  if (res[0]!=0) res[0][2]=a12;
  a13=(-a09);
  if (res[0]!=0) res[0][3]=a13;
  if (res[0]!=0) res[0][4]=a01;
  if (res[0]!=0) res[0][5]=a00;
  a14=(a04*a05);
  a06=(a03*a06);
  a14=(a14-a06);
  a02=(a02*a14);
  a10=(a10*a04);
  a10=(a02+a10);
  if (res[0]!=0) res[0][6]=a10;
  if (res[0]!=0) res[0][7]=a02;
  if (res[0]!=0) res[0][8]=a12;
  if (res[0]!=0) res[0][9]=a10;
  a12=(a14*a04);
  a06=(a08*a03);
  a12=(a12+a06);
  a06=arg[6]? arg[6][12] : 0;
  a12=(a12*a06);
  a06=arg[6]? arg[6][14] : 0;
  a06=(a12+a06);
  a15=arg[6]? arg[6][15] : 0;
  a12=(a12+a15);
  a06=(a06+a12);
  if (res[0]!=0) res[0][10]=a06;
  if (res[0]!=0) res[0][11]=a12;
  if (res[0]!=0) res[0][12]=a13;
  if (res[0]!=0) res[0][13]=a02;
  if (res[0]!=0) res[0][14]=a12;
  if (res[0]!=0) res[0][15]=a15;
  a13=arg[7]? arg[7][0] : 0;
  a16=(a13*a03);
  a17=arg[7]? arg[7][1] : 0;
  a05=(a03*a05);
  a05=(a05+a07);
  a07=(a17*a05);
  a16=(a16+a07);
  a07=arg[8]? arg[8][0] : 0;
  a18=(a16*a07);
  a19=(a13+a17);
  a20=(a18*a19);
  a21=(a20/a00);
  a11=(a11/a00);
  a22=arg[0]? arg[0][1] : 0;
  a23=arg[6]? arg[6][2] : 0;
  a24=arg[6]? arg[6][6] : 0;
  a23=(a23-a24);
  a25=(a23*a03);
  a26=(a22+a25);
  a27=arg[6]? arg[6][7] : 0;
  a28=(a08*a27);
  a26=(a26+a28);
  a29=(a22-a26);
  a30=(a17*a29);
  a31=(a18*a30);
  a32=(a13*a04);
  a33=(a17*a14);
  a32=(a32+a33);
  a33=(a32*a07);
  a34=arg[0]? arg[0][0] : 0;
  a35=(a04*a23);
  a36=(a34+a35);
  a37=(a14*a27);
  a36=(a36+a37);
  a38=(a36-a34);
  a39=(a17*a38);
  a40=(a33*a39);
  a31=(a31-a40);
  a24=(a24*a13);
  a40=(a27*a17);
  a24=(a24+a40);
  a40=(a07*a24);
  a41=casadi_sq(a16);
  a41=(a40*a41);
  a42=casadi_sq(a32);
  a40=(a40*a42);
  a41=(a41+a40);
  a40=1.;
  a42=arg[15]? arg[15][0] : 0;
  a40=(a40-a42);
  a43=arg[3]? arg[3][2] : 0;
  a44=cos(a43);
  a44=(a40*a44);
  a45=(a42*a32);
  a44=(a44+a45);
  a45=arg[11]? arg[11][1] : 0;
  a45=(a40*a45);
  a46=arg[14]? arg[14][0] : 0;
  a47=(a07*a46);
  a47=(a42*a47);
  a45=(a45-a47);
  a47=(a44*a45);
  a43=sin(a43);
  a43=(a40*a43);
  a48=(a42*a16);
  a43=(a43+a48);
  a48=arg[11]? arg[11][0] : 0;
  a48=(a40*a48);
  a49=(a43*a48);
  a47=(a47+a49);
  a49=arg[3]? arg[3][1] : 0;
  a49=(a40*a49);
  a50=(a22*a13);
  a26=(a26*a17);
  a50=(a50+a26);
  a26=arg[13]? arg[13][0] : 0;
  a26=(a26-a24);
  a51=(a26*a16);
  a51=(a50+a51);
  a52=(a07*a32);
  a52=(a46*a52);
  a51=(a51+a52);
  a51=(a42*a51);
  a49=(a49+a51);
  a49=(a47+a49);
  a51=(a16*a24);
  a49=(a49+a51);
  a49=(a49-a50);
  a50=(a18*a49);
  a41=(a41-a50);
  a44=(a44*a48);
  a43=(a43*a45);
  a44=(a44-a43);
  a43=arg[3]? arg[3][0] : 0;
  a40=(a40*a43);
  a13=(a34*a13);
  a36=(a36*a17);
  a13=(a13+a36);
  a26=(a26*a32);
  a26=(a13+a26);
  a36=(a07*a16);
  a46=(a46*a36);
  a26=(a26-a46);
  a42=(a42*a26);
  a40=(a40+a42);
  a40=(a44+a40);
  a24=(a32*a24);
  a40=(a40+a24);
  a40=(a40-a13);
  a13=(a33*a40);
  a41=(a41-a13);
  a13=(a41*a19);
  a31=(a31+a13);
  a13=(a11*a20);
  a13=(a31+a13);
  a10=(a10/a00);
  a24=(a33*a19);
  a42=(a10*a24);
  a13=(a13+a42);
  a42=casadi_sq(a11);
  a42=(a42*a00);
  a06=(a06-a42);
  a42=casadi_sq(a10);
  a42=(a42*a00);
  a06=(a06-a42);
  a42=(a13/a06);
  a09=(a09/a00);
  a26=(a09*a11);
  a26=(a26*a00);
  a12=(a12-a26);
  a02=(a02/a00);
  a26=(a02*a10);
  a26=(a26*a00);
  a12=(a12-a26);
  a12=(a12/a06);
  a41=(a41*a17);
  a26=(a17*a28);
  a46=(a18*a26);
  a36=(a17*a37);
  a43=(a33*a36);
  a46=(a46+a43);
  a41=(a41-a46);
  a46=(a09*a20);
  a46=(a41+a46);
  a43=(a02*a24);
  a46=(a46+a43);
  a13=(a12*a13);
  a46=(a46-a13);
  a13=casadi_sq(a09);
  a13=(a13*a00);
  a15=(a15-a13);
  a13=casadi_sq(a02);
  a13=(a13*a00);
  a15=(a15-a13);
  a13=casadi_sq(a12);
  a13=(a13*a06);
  a15=(a15-a13);
  a46=(a46/a15);
  a13=(a12*a46);
  a42=(a42-a13);
  a13=(a11*a42);
  a21=(a21+a13);
  a13=(a09*a46);
  a21=(a21+a13);
  a13=(a20*a21);
  a43=(a24/a00);
  a45=(a10*a42);
  a43=(a43+a45);
  a45=(a02*a46);
  a43=(a43+a45);
  a45=(a24*a43);
  a13=(a13+a45);
  a45=(a31*a42);
  a13=(a13+a45);
  a45=(a41*a46);
  a13=(a13+a45);
  a45=arg[9]? arg[9][0] : 0;
  a48=(a18/a45);
  a50=(a18*a48);
  a51=(a33/a45);
  a52=(a33*a51);
  a50=(a50+a52);
  a52=(a32*a44);
  a52=(a52*a07);
  a53=(a18*a47);
  a52=(a52+a53);
  a53=arg[10]? arg[10][0] : 0;
  a54=(a52/a53);
  a55=(a52*a54);
  a50=(a50+a55);
  a13=(a13+a50);
  if (res[1]!=0) res[1][0]=a13;
  a13=arg[12]? arg[12][0] : 0;
  a50=(a13*a42);
  a55=(a03*a21);
  a56=(a04*a43);
  a55=(a55+a56);
  a50=(a50-a55);
  if (res[1]!=0) res[1][1]=a50;
  a50=(a14*a38);
  a55=(a05*a29);
  a50=(a50-a55);
  a55=arg[12]? arg[12][1] : 0;
  a50=(a50+a55);
  a56=(a50*a42);
  a57=(a05*a21);
  a58=(a14*a43);
  a57=(a57+a58);
  a56=(a56-a57);
  a57=(a05*a28);
  a58=(a14*a37);
  a57=(a57+a58);
  a57=(a57+a55);
  a55=(a57*a46);
  a56=(a56+a55);
  if (res[1]!=0) res[1][2]=a56;
  a56=(a11*a03);
  a56=(a13-a56);
  a55=(a10*a04);
  a56=(a56-a55);
  a55=(a56/a06);
  a58=(a09*a03);
  a59=(a02*a04);
  a58=(a58+a59);
  a56=(a12*a56);
  a58=(a58+a56);
  a58=(a58/a15);
  a56=(a12*a58);
  a55=(a55+a56);
  a56=(a11*a55);
  a59=(a03/a00);
  a56=(a56-a59);
  a59=(a09*a58);
  a56=(a56-a59);
  a59=(a20*a56);
  a60=(a04/a00);
  a61=(a10*a55);
  a60=(a60-a61);
  a61=(a02*a58);
  a60=(a60+a61);
  a61=(a24*a60);
  a59=(a59-a61);
  a61=(a31*a55);
  a59=(a59+a61);
  a61=(a41*a58);
  a59=(a59-a61);
  if (res[1]!=0) res[1][3]=a59;
  a59=(a04*a60);
  a61=(a03*a56);
  a59=(a59-a61);
  a61=(a13*a55);
  a59=(a59+a61);
  if (res[1]!=0) res[1][4]=a59;
  a59=(a14*a60);
  a61=(a05*a56);
  a59=(a59-a61);
  a61=(a50*a55);
  a59=(a59+a61);
  a61=(a57*a58);
  a59=(a59-a61);
  if (res[1]!=0) res[1][5]=a59;
  a59=(a11*a05);
  a59=(a50-a59);
  a61=(a10*a14);
  a59=(a59-a61);
  a61=(a59/a06);
  a62=(a09*a05);
  a62=(a57-a62);
  a63=(a02*a14);
  a62=(a62-a63);
  a59=(a12*a59);
  a62=(a62-a59);
  a62=(a62/a15);
  a59=(a12*a62);
  a61=(a61-a59);
  a59=(a11*a61);
  a63=(a05/a00);
  a59=(a59-a63);
  a63=(a09*a62);
  a59=(a59+a63);
  a63=(a20*a59);
  a64=(a14/a00);
  a65=(a10*a61);
  a64=(a64-a65);
  a65=(a02*a62);
  a64=(a64-a65);
  a65=(a24*a64);
  a63=(a63-a65);
  a65=(a31*a61);
  a63=(a63+a65);
  a65=(a41*a62);
  a63=(a63+a65);
  if (res[1]!=0) res[1][6]=a63;
  a63=(a04*a64);
  a65=(a03*a59);
  a63=(a63-a65);
  a65=(a13*a61);
  a63=(a63+a65);
  if (res[1]!=0) res[1][7]=a63;
  a63=(a14*a64);
  a65=(a05*a59);
  a63=(a63-a65);
  a65=(a50*a61);
  a63=(a63+a65);
  a65=(a57*a62);
  a63=(a63+a65);
  if (res[1]!=0) res[1][8]=a63;
  a63=arg[1]? arg[1][3] : 0;
  a65=arg[1]? arg[1][2] : 0;
  a66=(a63+a65);
  a66=casadi_sq(a66);
  a67=(a66*a37);
  a68=casadi_sq(a65);
  a69=(a68*a35);
  a67=(a67+a69);
  a69=arg[6]? arg[6][1] : 0;
  a67=(a67*a69);
  a70=(a67/a00);
  a71=(a11*a67);
  a72=(a25+a22);
  a73=(a28+a72);
  a73=(a67*a73);
  a74=(a66*a28);
  a25=(a68*a25);
  a74=(a74+a25);
  a35=(a35+a34);
  a25=(a37+a35);
  a25=(a74*a25);
  a25=(a25*a69);
  a73=(a73-a25);
  a22=(a67*a22);
  a22=(a73-a22);
  a74=(a74*a69);
  a34=(a74*a34);
  a22=(a22+a34);
  a71=(a71-a22);
  a22=(a10*a74);
  a71=(a71-a22);
  a06=(a71/a06);
  a22=arg[2]? arg[2][0] : 0;
  a72=(a67*a72);
  a73=(a73-a72);
  a35=(a74*a35);
  a73=(a73+a35);
  a22=(a22-a73);
  a67=(a09*a67);
  a22=(a22+a67);
  a67=(a02*a74);
  a22=(a22-a67);
  a71=(a12*a71);
  a22=(a22-a71);
  a22=(a22/a15);
  a12=(a12*a22);
  a06=(a06-a12);
  a11=(a11*a06);
  a70=(a70+a11);
  a09=(a09*a22);
  a70=(a70+a09);
  a20=(a20*a70);
  a74=(a74/a00);
  a10=(a10*a06);
  a74=(a74-a10);
  a02=(a02*a22);
  a74=(a74-a02);
  a24=(a24*a74);
  a20=(a20-a24);
  a31=(a31*a06);
  a20=(a20+a31);
  a41=(a41*a22);
  a20=(a20+a41);
  a41=arg[5]? arg[5][1] : 0;
  a41=(a41/a45);
  a31=(a33*a41);
  a24=arg[5]? arg[5][0] : 0;
  a24=(a24/a45);
  a45=(a18*a24);
  a31=(a31-a45);
  a45=arg[5]? arg[5][2] : 0;
  a45=(a45/a53);
  a52=(a52*a45);
  a31=(a31+a52);
  a20=(a20+a31);
  a31=arg[1]? arg[1][0] : 0;
  a52=(a19*a31);
  a30=(a30*a65);
  a52=(a52+a30);
  a26=(a26*a63);
  a52=(a52-a26);
  a52=(a33*a52);
  a26=(a19*a65);
  a30=(a17*a63);
  a26=(a26+a30);
  a30=(a52*a26);
  a27=(a27*a66);
  a66=(a14*a27);
  a68=(a68*a23);
  a23=(a04*a68);
  a66=(a66+a23);
  a23=(a66*a17);
  a23=(a18*a23);
  a30=(a30-a23);
  a23=arg[1]? arg[1][1] : 0;
  a19=(a19*a23);
  a39=(a39*a65);
  a19=(a19+a39);
  a36=(a36*a63);
  a19=(a19+a36);
  a19=(a18*a19);
  a36=(a19*a26);
  a30=(a30+a36);
  a52=(a52+a19);
  a47=(a47*a33);
  a44=(a18*a44);
  a19=(a47-a44);
  a36=arg[4]? arg[4][2] : 0;
  a39=(a19*a36);
  a52=(a52+a39);
  a39=arg[4]? arg[4][0] : 0;
  a39=(a33*a39);
  a52=(a52-a39);
  a53=arg[4]? arg[4][1] : 0;
  a18=(a18*a53);
  a52=(a52-a18);
  a53=(a49*a33);
  a02=(a16*a40);
  a02=(a02*a07);
  a53=(a53-a02);
  a02=(a53*a26);
  a52=(a52-a02);
  a52=(a26*a52);
  a30=(a30+a52);
  a19=(a19*a26);
  a44=(a44-a47);
  a44=(a36*a44);
  a19=(a19+a44);
  a36=(a36*a19);
  a30=(a30+a36);
  a39=(a39*a26);
  a30=(a30-a39);
  a18=(a18*a26);
  a30=(a30-a18);
  a27=(a27*a08);
  a68=(a68*a03);
  a27=(a27+a68);
  a17=(a27*a17);
  a33=(a33*a17);
  a30=(a30+a33);
  a20=(a20+a30);
  if (res[2]!=0) res[2][0]=a20;
  a20=(a04*a74);
  a30=(a03*a70);
  a20=(a20-a30);
  a13=(a13*a06);
  a20=(a20+a13);
  a03=(a03*a23);
  a03=(a03*a65);
  a04=(a04*a31);
  a04=(a04*a65);
  a03=(a03+a04);
  a20=(a20-a03);
  if (res[2]!=0) res[2][1]=a20;
  a20=(a14*a74);
  a03=(a05*a70);
  a20=(a20-a03);
  a50=(a50*a06);
  a20=(a20+a50);
  a57=(a57*a22);
  a20=(a20+a57);
  a66=(a05*a66);
  a27=(a14*a27);
  a66=(a66-a27);
  a38=(a38*a65);
  a23=(a23+a38);
  a37=(a37*a63);
  a23=(a23+a37);
  a05=(a05*a23);
  a23=(a65+a63);
  a05=(a05*a23);
  a66=(a66-a05);
  a29=(a29*a65);
  a31=(a31+a29);
  a28=(a28*a63);
  a31=(a31-a28);
  a14=(a14*a31);
  a14=(a14*a23);
  a66=(a66-a14);
  a20=(a20+a66);
  if (res[2]!=0) res[2][2]=a20;
  if (res[3]!=0) res[3][0]=a70;
  if (res[3]!=0) res[3][1]=a74;
  if (res[3]!=0) res[3][2]=a06;
  if (res[3]!=0) res[3][3]=a22;
  if (res[4]!=0) res[4][0]=a24;
  if (res[4]!=0) res[4][1]=a41;
  if (res[4]!=0) res[4][2]=a45;
  if (res[5]!=0) res[5][0]=a21;
  a43=(-a43);
  if (res[5]!=0) res[5][1]=a43;
  if (res[5]!=0) res[5][2]=a42;
  if (res[5]!=0) res[5][3]=a46;
  if (res[5]!=0) res[5][4]=a56;
  if (res[5]!=0) res[5][5]=a60;
  if (res[5]!=0) res[5][6]=a55;
  a58=(-a58);
  if (res[5]!=0) res[5][7]=a58;
  if (res[5]!=0) res[5][8]=a59;
  if (res[5]!=0) res[5][9]=a64;
  if (res[5]!=0) res[5][10]=a61;
  if (res[5]!=0) res[5][11]=a62;
  a48=(-a48);
  if (res[6]!=0) res[6][0]=a48;
  if (res[6]!=0) res[6][1]=a51;
  if (res[6]!=0) res[6][2]=a54;
  if (res[6]!=0) res[6][3]=a01;
  if (res[6]!=0) res[6][4]=a01;
  if (res[6]!=0) res[6][5]=a01;
  if (res[6]!=0) res[6][6]=a01;
  if (res[6]!=0) res[6][7]=a01;
  if (res[6]!=0) res[6][8]=a01;
  if (res[7]!=0) res[7][0]=a53;
  a16=(a16*a49);
  a32=(a32*a40);
  a16=(a16+a32);
  if (res[8]!=0) res[8][0]=a16;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_n_in(void) { return 16;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_contact_system_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_name_in(casadi_int i) {
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
    case 13: return "contact_offset";
    case 14: return "object_distance";
    case 15: return "placed";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_name_out(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_sparsity_in(casadi_int i) {
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
    case 13: return casadi_s1;
    case 14: return casadi_s1;
    case 15: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s7;
    case 6: return casadi_s6;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_contact_system(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[16];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 76);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 16; ++k) a[k] = 0;
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
    a[14] = arg[14] + i * stride[14];
    a[15] = arg[15] + i * stride[15];
    r[0] = res[0] + i * 16;
    r[1] = res[1] + i * 9;
    r[2] = res[2] + i * 3;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 12;
    r[6] = res[6] + i * 9;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na1_contact_system(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
