/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_row() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_contact_row_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_contact_row_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};
static const casadi_int casadi_s3[3] = {2, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};
static const casadi_int casadi_s5[3] = {6, 1, 1};
static const casadi_int casadi_s6[3] = {1, 7, 1};
static const casadi_int casadi_s7[3] = {1, 6, 1};
static const casadi_int casadi_s8[3] = {1, 1, 1};

/* snakecg_sp1_contact_row:(q[8],v[7],K[71],link[2],point[3],normal[3],rho[3],v_obj[6])->(a_snake[1x7],g_obj[1x6],adot_v,position[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52;
  a00=1.;
  a01=-2.;
  a02=arg[0]? arg[0][4] : 0;
  a03=casadi_sq(a02);
  a03=(a01*a03);
  a04=(a00+a03);
  a05=arg[0]? arg[0][5] : 0;
  a06=casadi_sq(a05);
  a06=(a01*a06);
  a04=(a04+a06);
  a07=arg[5]? arg[5][0] : 0;
  a08=(a04*a07);
  a09=arg[0]? arg[0][6] : 0;
  a10=(2.*a09);
  a11=(a10*a05);
  a12=arg[0]? arg[0][3] : 0;
  a13=(2.*a12);
  a14=(a13*a02);
  a11=(a11+a14);
  a15=arg[5]? arg[5][1] : 0;
  a16=(a11*a15);
  a08=(a08+a16);
  a09=(a01*a09);
  a16=(a09*a02);
  a13=(a13*a05);
  a16=(a16+a13);
  a17=arg[5]? arg[5][2] : 0;
  a18=(a16*a17);
  a08=(a08+a18);
  a08=(-a08);
  if (res[0]!=0) res[0][0]=a08;
  a08=(a09*a05);
  a08=(a08+a14);
  a14=(a08*a07);
  a18=casadi_sq(a12);
  a01=(a01*a18);
  a00=(a00+a01);
  a06=(a00+a06);
  a01=(a06*a15);
  a14=(a14+a01);
  a01=(a10*a12);
  a18=(2.*a02);
  a18=(a18*a05);
  a01=(a01+a18);
  a05=(a01*a17);
  a14=(a14+a05);
  a14=(-a14);
  if (res[0]!=0) res[0][1]=a14;
  a10=(a10*a02);
  a10=(a10+a13);
  a13=(a10*a07);
  a09=(a09*a12);
  a09=(a09+a18);
  a18=(a09*a15);
  a13=(a13+a18);
  a00=(a00+a03);
  a03=(a00*a17);
  a13=(a13+a03);
  a13=(-a13);
  if (res[0]!=0) res[0][2]=a13;
  a13=arg[2]? arg[2][41] : 0;
  a03=(a13*a16);
  a18=arg[2]? arg[2][42] : 0;
  a12=(a18*a01);
  a03=(a03+a12);
  a12=arg[2]? arg[2][43] : 0;
  a02=(a12*a00);
  a03=(a03+a02);
  a02=arg[0]? arg[0][7] : 0;
  a14=cos(a02);
  a05=(a03*a14);
  a19=arg[2]? arg[2][44] : 0;
  a20=(a19*a16);
  a21=arg[2]? arg[2][45] : 0;
  a22=(a21*a01);
  a20=(a20+a22);
  a22=arg[2]? arg[2][46] : 0;
  a23=(a22*a00);
  a20=(a20+a23);
  a02=sin(a02);
  a23=(a20*a02);
  a05=(a05+a23);
  a23=arg[3]? arg[3][1] : 0;
  a05=(a05*a23);
  a24=arg[3]? arg[3][0] : 0;
  a25=(a16*a24);
  a05=(a05+a25);
  a25=arg[2]? arg[2][32] : 0;
  a25=(a25*a23);
  a25=(a24+a25);
  a26=arg[4]? arg[4][0] : 0;
  a25=(a25*a26);
  a27=arg[2]? arg[2][33] : 0;
  a27=(a27*a23);
  a28=arg[4]? arg[4][1] : 0;
  a27=(a27*a28);
  a25=(a25+a27);
  a27=arg[2]? arg[2][34] : 0;
  a27=(a27*a23);
  a29=arg[4]? arg[4][2] : 0;
  a27=(a27*a29);
  a25=(a25+a27);
  a05=(a05*a25);
  a20=(a20*a14);
  a03=(a03*a02);
  a20=(a20-a03);
  a20=(a20*a23);
  a03=(a01*a24);
  a20=(a20+a03);
  a03=arg[2]? arg[2][35] : 0;
  a03=(a03*a23);
  a03=(a03*a26);
  a27=arg[2]? arg[2][36] : 0;
  a27=(a27*a23);
  a27=(a24+a27);
  a27=(a27*a28);
  a03=(a03+a27);
  a27=arg[2]? arg[2][37] : 0;
  a27=(a27*a23);
  a27=(a27*a29);
  a03=(a03+a27);
  a20=(a20*a03);
  a05=(a05+a20);
  a20=arg[2]? arg[2][47] : 0;
  a27=(a20*a16);
  a30=arg[2]? arg[2][48] : 0;
  a31=(a30*a01);
  a27=(a27+a31);
  a31=arg[2]? arg[2][49] : 0;
  a32=(a31*a00);
  a27=(a27+a32);
  a32=(a27*a23);
  a33=(a00*a24);
  a32=(a32+a33);
  a33=arg[2]? arg[2][38] : 0;
  a33=(a33*a23);
  a33=(a33*a26);
  a26=arg[2]? arg[2][39] : 0;
  a26=(a26*a23);
  a26=(a26*a28);
  a33=(a33+a26);
  a26=arg[2]? arg[2][40] : 0;
  a26=(a26*a23);
  a26=(a24+a26);
  a26=(a26*a29);
  a33=(a33+a26);
  a32=(a32*a33);
  a05=(a05+a32);
  a32=arg[2]? arg[2][50] : 0;
  a26=(a16*a32);
  a29=arg[2]? arg[2][51] : 0;
  a28=(a01*a29);
  a26=(a26+a28);
  a28=arg[2]? arg[2][52] : 0;
  a34=(a00*a28);
  a26=(a26+a34);
  a34=arg[0]? arg[0][2] : 0;
  a35=(a26+a34);
  a36=(a35*a23);
  a37=(a24*a34);
  a36=(a36+a37);
  a36=(a05+a36);
  a34=(a36-a34);
  a37=(a11*a34);
  a38=(a13*a11);
  a39=(a18*a06);
  a38=(a38+a39);
  a39=(a12*a09);
  a38=(a38+a39);
  a39=(a38*a14);
  a40=(a19*a11);
  a41=(a21*a06);
  a40=(a40+a41);
  a41=(a22*a09);
  a40=(a40+a41);
  a41=(a40*a02);
  a39=(a39+a41);
  a39=(a39*a23);
  a41=(a11*a24);
  a39=(a39+a41);
  a39=(a39*a25);
  a40=(a40*a14);
  a38=(a38*a02);
  a40=(a40-a38);
  a40=(a40*a23);
  a38=(a06*a24);
  a40=(a40+a38);
  a40=(a40*a03);
  a39=(a39+a40);
  a40=(a20*a11);
  a38=(a30*a06);
  a40=(a40+a38);
  a38=(a31*a09);
  a40=(a40+a38);
  a38=(a40*a23);
  a41=(a09*a24);
  a38=(a38+a41);
  a38=(a38*a33);
  a39=(a39+a38);
  a38=(a11*a32);
  a41=(a06*a29);
  a38=(a38+a41);
  a41=(a09*a28);
  a38=(a38+a41);
  a41=arg[0]? arg[0][1] : 0;
  a42=(a38+a41);
  a43=(a42*a23);
  a44=(a24*a41);
  a43=(a43+a44);
  a43=(a39+a43);
  a41=(a43-a41);
  a44=(a16*a41);
  a37=(a37-a44);
  a37=(a07*a37);
  a13=(a13*a04);
  a18=(a18*a08);
  a13=(a13+a18);
  a12=(a12*a10);
  a13=(a13+a12);
  a12=(a13*a14);
  a19=(a19*a04);
  a21=(a21*a08);
  a19=(a19+a21);
  a22=(a22*a10);
  a19=(a19+a22);
  a22=(a19*a02);
  a12=(a12+a22);
  a12=(a12*a23);
  a22=(a04*a24);
  a12=(a12+a22);
  a12=(a12*a25);
  a19=(a19*a14);
  a13=(a13*a02);
  a19=(a19-a13);
  a19=(a19*a23);
  a13=(a08*a24);
  a19=(a19+a13);
  a19=(a19*a03);
  a12=(a12+a19);
  a20=(a20*a04);
  a30=(a30*a08);
  a20=(a20+a30);
  a31=(a31*a10);
  a20=(a20+a31);
  a31=(a20*a23);
  a30=(a10*a24);
  a31=(a31+a30);
  a31=(a31*a33);
  a12=(a12+a31);
  a32=(a04*a32);
  a29=(a08*a29);
  a32=(a32+a29);
  a28=(a10*a28);
  a32=(a32+a28);
  a28=arg[0]? arg[0][0] : 0;
  a29=(a32+a28);
  a31=(a29*a23);
  a33=(a24*a28);
  a31=(a31+a33);
  a31=(a12+a31);
  a28=(a31-a28);
  a33=(a16*a28);
  a30=(a04*a34);
  a33=(a33-a30);
  a33=(a15*a33);
  a37=(a37+a33);
  a33=(a04*a41);
  a30=(a11*a28);
  a33=(a33-a30);
  a33=(a17*a33);
  a37=(a37+a33);
  a37=(-a37);
  if (res[0]!=0) res[0][3]=a37;
  a37=(a06*a34);
  a33=(a01*a41);
  a37=(a37-a33);
  a37=(a07*a37);
  a33=(a01*a28);
  a30=(a08*a34);
  a33=(a33-a30);
  a33=(a15*a33);
  a37=(a37+a33);
  a33=(a08*a41);
  a30=(a06*a28);
  a33=(a33-a30);
  a33=(a17*a33);
  a37=(a37+a33);
  a37=(-a37);
  if (res[0]!=0) res[0][4]=a37;
  a37=(a09*a34);
  a33=(a00*a41);
  a37=(a37-a33);
  a37=(a07*a37);
  a33=(a00*a28);
  a34=(a10*a34);
  a33=(a33-a34);
  a33=(a15*a33);
  a37=(a37+a33);
  a41=(a10*a41);
  a28=(a09*a28);
  a41=(a41-a28);
  a41=(a17*a41);
  a37=(a37+a41);
  a37=(-a37);
  if (res[0]!=0) res[0][5]=a37;
  a37=(a07*a23);
  a35=(a36-a35);
  a41=(a40*a35);
  a42=(a43-a42);
  a28=(a27*a42);
  a41=(a41-a28);
  a37=(a37*a41);
  a41=(a15*a23);
  a29=(a31-a29);
  a28=(a27*a29);
  a35=(a20*a35);
  a28=(a28-a35);
  a41=(a41*a28);
  a37=(a37+a41);
  a41=(a17*a23);
  a42=(a20*a42);
  a29=(a40*a29);
  a42=(a42-a29);
  a41=(a41*a42);
  a37=(a37+a41);
  a37=(-a37);
  if (res[0]!=0) res[0][6]=a37;
  if (res[1]!=0) res[1][0]=a07;
  if (res[1]!=0) res[1][1]=a15;
  if (res[1]!=0) res[1][2]=a17;
  a37=arg[6]? arg[6][1] : 0;
  a41=(a17*a37);
  a42=arg[6]? arg[6][2] : 0;
  a29=(a15*a42);
  a41=(a41-a29);
  if (res[1]!=0) res[1][3]=a41;
  a41=(a07*a42);
  a29=arg[6]? arg[6][0] : 0;
  a28=(a17*a29);
  a41=(a41-a28);
  if (res[1]!=0) res[1][4]=a41;
  a41=(a15*a29);
  a28=(a07*a37);
  a41=(a41-a28);
  if (res[1]!=0) res[1][5]=a41;
  a41=arg[7]? arg[7][3] : 0;
  a28=(a37*a41);
  a35=arg[7]? arg[7][4] : 0;
  a33=(a29*a35);
  a28=(a28-a33);
  a33=(a28*a35);
  a34=arg[1]? arg[1][3] : 0;
  a30=(a11*a34);
  a19=arg[1]? arg[1][4] : 0;
  a03=(a06*a19);
  a30=(a30+a03);
  a03=arg[1]? arg[1][5] : 0;
  a13=(a09*a03);
  a30=(a30+a13);
  a13=arg[1]? arg[1][0] : 0;
  a02=(a16*a13);
  a14=arg[1]? arg[1][1] : 0;
  a25=(a01*a14);
  a02=(a02+a25);
  a25=arg[1]? arg[1][2] : 0;
  a22=(a00*a25);
  a02=(a02+a22);
  a22=(a30*a02);
  a16=(a16*a34);
  a01=(a01*a19);
  a16=(a16+a01);
  a00=(a00*a03);
  a16=(a16+a00);
  a11=(a11*a13);
  a06=(a06*a14);
  a11=(a11+a06);
  a09=(a09*a25);
  a11=(a11+a09);
  a09=(a16*a11);
  a22=(a22-a09);
  a09=(a22*a24);
  a34=(a04*a34);
  a19=(a08*a19);
  a34=(a34+a19);
  a03=(a10*a03);
  a34=(a34+a03);
  a03=(a38*a34);
  a19=(a32*a30);
  a06=(a03-a19);
  a00=(a30*a06);
  a22=(a22+a00);
  a32=(a32*a16);
  a00=(a26*a34);
  a01=(a32-a00);
  a21=(a16*a01);
  a22=(a22-a21);
  a22=(a22*a23);
  a09=(a09+a22);
  a22=arg[1]? arg[1][6] : 0;
  a21=(a20*a16);
  a18=(a27*a34);
  a21=(a21-a18);
  a21=(a22*a21);
  a21=(a21*a23);
  a18=(a21*a05);
  a09=(a09+a18);
  a18=(a30*a24);
  a44=(a40*a22);
  a44=(a30+a44);
  a44=(a44*a23);
  a18=(a18+a44);
  a44=(a34*a24);
  a45=(a20*a22);
  a45=(a34+a45);
  a45=(a45*a23);
  a44=(a44+a45);
  a45=(a39*a44);
  a46=(a12*a18);
  a47=(a45-a46);
  a48=(a18*a47);
  a09=(a09+a48);
  a48=(a40*a34);
  a20=(a20*a30);
  a48=(a48-a20);
  a48=(a22*a48);
  a48=(a48*a23);
  a20=(a48*a39);
  a09=(a09-a20);
  a20=(a16*a24);
  a49=(a27*a22);
  a49=(a16+a49);
  a49=(a49*a23);
  a20=(a20+a49);
  a49=(a12*a20);
  a50=(a05*a44);
  a51=(a49-a50);
  a52=(a20*a51);
  a09=(a09-a52);
  a33=(a33-a09);
  a09=arg[7]? arg[7][5] : 0;
  a29=(a29*a09);
  a52=(a42*a41);
  a29=(a29-a52);
  a52=(a29*a09);
  a33=(a33-a52);
  a33=(a07*a33);
  a42=(a42*a35);
  a37=(a37*a09);
  a42=(a42-a37);
  a37=(a42*a09);
  a04=(a04*a13);
  a08=(a08*a14);
  a04=(a04+a08);
  a10=(a10*a25);
  a04=(a04+a10);
  a10=(a16*a04);
  a25=(a34*a02);
  a10=(a10-a25);
  a25=(a10*a24);
  a26=(a26*a30);
  a38=(a38*a16);
  a08=(a26-a38);
  a14=(a16*a08);
  a10=(a10+a14);
  a06=(a34*a06);
  a10=(a10-a06);
  a10=(a10*a23);
  a25=(a25+a10);
  a48=(a48*a12);
  a25=(a25+a48);
  a48=(a05*a18);
  a10=(a39*a20);
  a06=(a48-a10);
  a20=(a20*a06);
  a25=(a25+a20);
  a27=(a27*a30);
  a40=(a40*a16);
  a27=(a27-a40);
  a22=(a22*a27);
  a22=(a22*a23);
  a05=(a22*a05);
  a25=(a25-a05);
  a47=(a44*a47);
  a25=(a25-a47);
  a37=(a37-a25);
  a25=(a28*a41);
  a37=(a37-a25);
  a37=(a15*a37);
  a33=(a33+a37);
  a37=(a29*a41);
  a25=(a34*a11);
  a47=(a30*a04);
  a25=(a25-a47);
  a47=(a25*a24);
  a34=(a34*a01);
  a25=(a25+a34);
  a30=(a30*a08);
  a25=(a25-a30);
  a25=(a25*a23);
  a47=(a47+a25);
  a22=(a22*a39);
  a47=(a47+a22);
  a44=(a44*a51);
  a47=(a47+a44);
  a21=(a21*a12);
  a47=(a47-a21);
  a18=(a18*a06);
  a47=(a47-a18);
  a37=(a37-a47);
  a47=(a42*a35);
  a37=(a37-a47);
  a37=(a17*a37);
  a33=(a33+a37);
  a37=(a07*a09);
  a47=(a17*a41);
  a37=(a37-a47);
  a47=arg[7]? arg[7][1] : 0;
  a29=(a29+a47);
  a47=(a24*a11);
  a11=(a11+a32);
  a11=(a11-a00);
  a11=(a23*a11);
  a47=(a47+a11);
  a47=(a47+a49);
  a47=(a47-a50);
  a29=(a29-a47);
  a37=(a37*a29);
  a33=(a33+a37);
  a41=(a15*a41);
  a07=(a07*a35);
  a41=(a41-a07);
  a07=arg[7]? arg[7][2] : 0;
  a28=(a28+a07);
  a07=(a24*a02);
  a02=(a02+a03);
  a02=(a02-a19);
  a02=(a23*a02);
  a07=(a07+a02);
  a07=(a07+a45);
  a07=(a07-a46);
  a28=(a28-a07);
  a41=(a41*a28);
  a33=(a33+a41);
  a17=(a17*a35);
  a15=(a15*a09);
  a17=(a17-a15);
  a15=arg[7]? arg[7][0] : 0;
  a42=(a42+a15);
  a24=(a24*a04);
  a04=(a04+a26);
  a04=(a04-a38);
  a23=(a23*a04);
  a24=(a24+a23);
  a24=(a24+a48);
  a24=(a24-a10);
  a42=(a42-a24);
  a17=(a17*a42);
  a33=(a33+a17);
  if (res[2]!=0) res[2][0]=a33;
  if (res[3]!=0) res[3][0]=a31;
  if (res[3]!=0) res[3][1]=a43;
  if (res[3]!=0) res[3][2]=a36;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_contact_row_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_contact_row_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_contact_row_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_contact_row_n_in(void) { return 8;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_contact_row_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_contact_row_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_contact_row_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "link";
    case 4: return "point";
    case 5: return "normal";
    case 6: return "rho";
    case 7: return "v_obj";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_contact_row_name_out(casadi_int i) {
  switch (i) {
    case 0: return "a_snake";
    case 1: return "g_obj";
    case 2: return "adot_v";
    case 3: return "position";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_contact_row_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s4;
    case 5: return casadi_s4;
    case 6: return casadi_s4;
    case 7: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_contact_row_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s6;
    case 1: return casadi_s7;
    case 2: return casadi_s8;
    case 3: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_contact_row_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

/* Cosines and sines of a block of angles in one loop without calls or branches, which the
 * compiler turns into vector instructions (16 angles per call): the sines and cosines of
 * the angles of 16 samples are computed at once, then the function without its own calls
 * runs per sample.
 * Reduction by pi/2 in three parts (Cody and Waite, exact products for |x| < 2^20 pi/2) and
 * fdlibm's polynomials of sin and cos on [-pi/4, pi/4] (errors below one unit in the last
 * place there); the quadrant turns the pair by n pi/2 with factors 0, +1, -1 (exact). An
 * angle with |x| above SNAKECG_SINCOS_MAX, or not a number, is left to the C library
 * (snakecg_sincos_large). */
#define SNAKECG_SINCOS_BLOCK 16
#define SNAKECG_SINCOS_MAX 8.0e5

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 6 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("avx2", "default")))
#endif
static void snakecg_sincos_block(const casadi_real* restrict x, casadi_real* restrict c,
                                 casadi_real* restrict s) {
  const casadi_real round = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to integers */
  const casadi_real two_over_pi = 6.36619772367581382433e-01;
  const casadi_real pio2_1 = 1.57079632673412561417e+00; /* pi/2: first 33 bits */
  const casadi_real pio2_2 = 6.07710050630396597660e-11; /* next 33 bits */
  const casadi_real pio2_3 = 2.02226624871116645580e-21; /* the rest */
  const casadi_real S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
      S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
      S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const casadi_real C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
      C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
      C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  int i;
  for (i = 0; i < SNAKECG_SINCOS_BLOCK; ++i) {
    casadi_real n = (x[i] * two_over_pi + round) - round;  /* nearest multiple of pi/2 */
    casadi_real m = n - 4.0 * ((0.25 * n + round) - round); /* n mod 4 in -2..2 */
    casadi_real am = fabs(m);
    casadi_real cq = 1.0 - am, sq = m * (2.0 - am);          /* cos, sin of n pi/2 */
    casadi_real y = ((x[i] - n * pio2_1) - n * pio2_2) - n * pio2_3;
    casadi_real z = y * y;
    casadi_real sy = y + z * y * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    casadi_real hz = 0.5 * z, w = 1.0 - hz;
    casadi_real cy = w + (((1.0 - w) - hz)
                          + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    c[i] = cy * cq - sy * sq;
    s[i] = sy * cq + cy * sq;
  }
}

/* the C library's cos and sin where |x| > SNAKECG_SINCOS_MAX or x is not a number (the
 * driver calls this only when it met such an angle while gathering them) */
static void snakecg_sincos_large(const casadi_real* x, casadi_real* c, casadi_real* s,
                                 casadi_int n) {
  casadi_int i;
  for (i = 0; i < n; ++i) {
    if (!(fabs(x[i]) <= SNAKECG_SINCOS_MAX)) {
      c[i] = cos(x[i]);
      s[i] = sin(x[i]);
    }
  }
}

/* snakecg_sp1_contact_row_sincos: 561 CasADi instructions, printed one per line */
static void snakecg_sp1_contact_row_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    const casadi_real* restrict arg6,
    const casadi_real* restrict arg7,
    const casadi_real* restrict arg8,
    const casadi_real* restrict arg9,
    casadi_real* restrict res0,
    casadi_real* restrict res1,
    casadi_real* restrict res2,
    casadi_real* restrict res3) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52;
  w0 = 1.0;
  w1 = (-2.0);
  w2 = arg0[4];
  w3 = w2 * w2;
  w3 = w1 * w3;
  w4 = w0 + w3;
  w5 = arg0[5];
  w6 = w5 * w5;
  w6 = w1 * w6;
  w4 = w4 + w6;
  w7 = arg5[0];
  w8 = w4 * w7;
  w9 = arg0[6];
  w10 = w9 + w9;
  w11 = w10 * w5;
  w12 = arg0[3];
  w13 = w12 + w12;
  w14 = w13 * w2;
  w11 = w11 + w14;
  w15 = arg5[1];
  w16 = w11 * w15;
  w8 = w8 + w16;
  w9 = w1 * w9;
  w16 = w9 * w2;
  w13 = w13 * w5;
  w16 = w16 + w13;
  w17 = arg5[2];
  w18 = w16 * w17;
  w8 = w8 + w18;
  w8 = -w8;
  res0[0] = w8;
  w8 = w9 * w5;
  w8 = w8 + w14;
  w14 = w8 * w7;
  w18 = w12 * w12;
  w1 = w1 * w18;
  w0 = w0 + w1;
  w6 = w0 + w6;
  w1 = w6 * w15;
  w14 = w14 + w1;
  w1 = w10 * w12;
  w18 = w2 + w2;
  w18 = w18 * w5;
  w1 = w1 + w18;
  w5 = w1 * w17;
  w14 = w14 + w5;
  w14 = -w14;
  res0[1] = w14;
  w10 = w10 * w2;
  w10 = w10 + w13;
  w13 = w10 * w7;
  w9 = w9 * w12;
  w9 = w9 + w18;
  w18 = w9 * w15;
  w13 = w13 + w18;
  w0 = w0 + w3;
  w3 = w0 * w17;
  w13 = w13 + w3;
  w13 = -w13;
  res0[2] = w13;
  w13 = arg2[41];
  w3 = w13 * w16;
  w18 = arg2[42];
  w12 = w18 * w1;
  w3 = w3 + w12;
  w12 = arg2[43];
  w2 = w12 * w0;
  w3 = w3 + w2;
  w2 = arg8[0];
  w14 = w3 * w2;
  w5 = arg2[44];
  w19 = w5 * w16;
  w20 = arg2[45];
  w21 = w20 * w1;
  w19 = w19 + w21;
  w21 = arg2[46];
  w22 = w21 * w0;
  w19 = w19 + w22;
  w22 = arg9[0];
  w23 = w19 * w22;
  w14 = w14 + w23;
  w23 = arg3[1];
  w14 = w14 * w23;
  w24 = arg3[0];
  w25 = w16 * w24;
  w14 = w14 + w25;
  w25 = arg2[32];
  w25 = w25 * w23;
  w25 = w24 + w25;
  w26 = arg4[0];
  w25 = w25 * w26;
  w27 = arg2[33];
  w27 = w27 * w23;
  w28 = arg4[1];
  w27 = w27 * w28;
  w25 = w25 + w27;
  w27 = arg2[34];
  w27 = w27 * w23;
  w29 = arg4[2];
  w27 = w27 * w29;
  w25 = w25 + w27;
  w14 = w14 * w25;
  w19 = w19 * w2;
  w3 = w3 * w22;
  w19 = w19 - w3;
  w19 = w19 * w23;
  w3 = w1 * w24;
  w19 = w19 + w3;
  w3 = arg2[35];
  w3 = w3 * w23;
  w3 = w3 * w26;
  w27 = arg2[36];
  w27 = w27 * w23;
  w27 = w24 + w27;
  w27 = w27 * w28;
  w3 = w3 + w27;
  w27 = arg2[37];
  w27 = w27 * w23;
  w27 = w27 * w29;
  w3 = w3 + w27;
  w19 = w19 * w3;
  w14 = w14 + w19;
  w19 = arg2[47];
  w27 = w19 * w16;
  w30 = arg2[48];
  w31 = w30 * w1;
  w27 = w27 + w31;
  w31 = arg2[49];
  w32 = w31 * w0;
  w27 = w27 + w32;
  w32 = w27 * w23;
  w33 = w0 * w24;
  w32 = w32 + w33;
  w33 = arg2[38];
  w33 = w33 * w23;
  w33 = w33 * w26;
  w26 = arg2[39];
  w26 = w26 * w23;
  w26 = w26 * w28;
  w33 = w33 + w26;
  w26 = arg2[40];
  w26 = w26 * w23;
  w26 = w24 + w26;
  w26 = w26 * w29;
  w33 = w33 + w26;
  w32 = w32 * w33;
  w14 = w14 + w32;
  w32 = arg2[50];
  w26 = w16 * w32;
  w29 = arg2[51];
  w28 = w1 * w29;
  w26 = w26 + w28;
  w28 = arg2[52];
  w34 = w0 * w28;
  w26 = w26 + w34;
  w34 = arg0[2];
  w35 = w26 + w34;
  w36 = w35 * w23;
  w37 = w24 * w34;
  w36 = w36 + w37;
  w36 = w14 + w36;
  w34 = w36 - w34;
  w37 = w11 * w34;
  w38 = w13 * w11;
  w39 = w18 * w6;
  w38 = w38 + w39;
  w39 = w12 * w9;
  w38 = w38 + w39;
  w39 = w38 * w2;
  w40 = w5 * w11;
  w41 = w20 * w6;
  w40 = w40 + w41;
  w41 = w21 * w9;
  w40 = w40 + w41;
  w41 = w40 * w22;
  w39 = w39 + w41;
  w39 = w39 * w23;
  w41 = w11 * w24;
  w39 = w39 + w41;
  w39 = w39 * w25;
  w40 = w40 * w2;
  w38 = w38 * w22;
  w40 = w40 - w38;
  w40 = w40 * w23;
  w38 = w6 * w24;
  w40 = w40 + w38;
  w40 = w40 * w3;
  w39 = w39 + w40;
  w40 = w19 * w11;
  w38 = w30 * w6;
  w40 = w40 + w38;
  w38 = w31 * w9;
  w40 = w40 + w38;
  w38 = w40 * w23;
  w41 = w9 * w24;
  w38 = w38 + w41;
  w38 = w38 * w33;
  w39 = w39 + w38;
  w38 = w11 * w32;
  w41 = w6 * w29;
  w38 = w38 + w41;
  w41 = w9 * w28;
  w38 = w38 + w41;
  w41 = arg0[1];
  w42 = w38 + w41;
  w43 = w42 * w23;
  w44 = w24 * w41;
  w43 = w43 + w44;
  w43 = w39 + w43;
  w41 = w43 - w41;
  w44 = w16 * w41;
  w37 = w37 - w44;
  w37 = w7 * w37;
  w13 = w13 * w4;
  w18 = w18 * w8;
  w13 = w13 + w18;
  w12 = w12 * w10;
  w13 = w13 + w12;
  w12 = w13 * w2;
  w5 = w5 * w4;
  w20 = w20 * w8;
  w5 = w5 + w20;
  w21 = w21 * w10;
  w5 = w5 + w21;
  w21 = w5 * w22;
  w12 = w12 + w21;
  w12 = w12 * w23;
  w21 = w4 * w24;
  w12 = w12 + w21;
  w12 = w12 * w25;
  w5 = w5 * w2;
  w13 = w13 * w22;
  w5 = w5 - w13;
  w5 = w5 * w23;
  w13 = w8 * w24;
  w5 = w5 + w13;
  w5 = w5 * w3;
  w12 = w12 + w5;
  w19 = w19 * w4;
  w30 = w30 * w8;
  w19 = w19 + w30;
  w31 = w31 * w10;
  w19 = w19 + w31;
  w31 = w19 * w23;
  w30 = w10 * w24;
  w31 = w31 + w30;
  w31 = w31 * w33;
  w12 = w12 + w31;
  w32 = w4 * w32;
  w29 = w8 * w29;
  w32 = w32 + w29;
  w28 = w10 * w28;
  w32 = w32 + w28;
  w28 = arg0[0];
  w29 = w32 + w28;
  w31 = w29 * w23;
  w33 = w24 * w28;
  w31 = w31 + w33;
  w31 = w12 + w31;
  w28 = w31 - w28;
  w33 = w16 * w28;
  w30 = w4 * w34;
  w33 = w33 - w30;
  w33 = w15 * w33;
  w37 = w37 + w33;
  w33 = w4 * w41;
  w30 = w11 * w28;
  w33 = w33 - w30;
  w33 = w17 * w33;
  w37 = w37 + w33;
  w37 = -w37;
  res0[3] = w37;
  w37 = w6 * w34;
  w33 = w1 * w41;
  w37 = w37 - w33;
  w37 = w7 * w37;
  w33 = w1 * w28;
  w30 = w8 * w34;
  w33 = w33 - w30;
  w33 = w15 * w33;
  w37 = w37 + w33;
  w33 = w8 * w41;
  w30 = w6 * w28;
  w33 = w33 - w30;
  w33 = w17 * w33;
  w37 = w37 + w33;
  w37 = -w37;
  res0[4] = w37;
  w37 = w9 * w34;
  w33 = w0 * w41;
  w37 = w37 - w33;
  w37 = w7 * w37;
  w33 = w0 * w28;
  w34 = w10 * w34;
  w33 = w33 - w34;
  w33 = w15 * w33;
  w37 = w37 + w33;
  w41 = w10 * w41;
  w28 = w9 * w28;
  w41 = w41 - w28;
  w41 = w17 * w41;
  w37 = w37 + w41;
  w37 = -w37;
  res0[5] = w37;
  w37 = w7 * w23;
  w35 = w36 - w35;
  w41 = w40 * w35;
  w42 = w43 - w42;
  w28 = w27 * w42;
  w41 = w41 - w28;
  w37 = w37 * w41;
  w41 = w15 * w23;
  w29 = w31 - w29;
  w28 = w27 * w29;
  w35 = w19 * w35;
  w28 = w28 - w35;
  w41 = w41 * w28;
  w37 = w37 + w41;
  w41 = w17 * w23;
  w42 = w19 * w42;
  w29 = w40 * w29;
  w42 = w42 - w29;
  w41 = w41 * w42;
  w37 = w37 + w41;
  w37 = -w37;
  res0[6] = w37;
  res1[0] = w7;
  res1[1] = w15;
  res1[2] = w17;
  w37 = arg6[1];
  w41 = w17 * w37;
  w42 = arg6[2];
  w29 = w15 * w42;
  w41 = w41 - w29;
  res1[3] = w41;
  w41 = w7 * w42;
  w29 = arg6[0];
  w28 = w17 * w29;
  w41 = w41 - w28;
  res1[4] = w41;
  w41 = w15 * w29;
  w28 = w7 * w37;
  w41 = w41 - w28;
  res1[5] = w41;
  w41 = arg7[3];
  w28 = w37 * w41;
  w35 = arg7[4];
  w33 = w29 * w35;
  w28 = w28 - w33;
  w33 = w28 * w35;
  w34 = arg1[3];
  w30 = w11 * w34;
  w5 = arg1[4];
  w3 = w6 * w5;
  w30 = w30 + w3;
  w3 = arg1[5];
  w13 = w9 * w3;
  w30 = w30 + w13;
  w13 = arg1[0];
  w22 = w16 * w13;
  w2 = arg1[1];
  w25 = w1 * w2;
  w22 = w22 + w25;
  w25 = arg1[2];
  w21 = w0 * w25;
  w22 = w22 + w21;
  w21 = w30 * w22;
  w16 = w16 * w34;
  w1 = w1 * w5;
  w16 = w16 + w1;
  w0 = w0 * w3;
  w16 = w16 + w0;
  w11 = w11 * w13;
  w6 = w6 * w2;
  w11 = w11 + w6;
  w9 = w9 * w25;
  w11 = w11 + w9;
  w9 = w16 * w11;
  w21 = w21 - w9;
  w9 = w21 * w24;
  w34 = w4 * w34;
  w5 = w8 * w5;
  w34 = w34 + w5;
  w3 = w10 * w3;
  w34 = w34 + w3;
  w3 = w38 * w34;
  w5 = w32 * w30;
  w6 = w3 - w5;
  w0 = w30 * w6;
  w21 = w21 + w0;
  w32 = w32 * w16;
  w0 = w26 * w34;
  w1 = w32 - w0;
  w20 = w16 * w1;
  w21 = w21 - w20;
  w21 = w21 * w23;
  w9 = w9 + w21;
  w21 = arg1[6];
  w20 = w19 * w16;
  w18 = w27 * w34;
  w20 = w20 - w18;
  w20 = w21 * w20;
  w20 = w20 * w23;
  w18 = w20 * w14;
  w9 = w9 + w18;
  w18 = w30 * w24;
  w44 = w40 * w21;
  w44 = w30 + w44;
  w44 = w44 * w23;
  w18 = w18 + w44;
  w44 = w34 * w24;
  w45 = w19 * w21;
  w45 = w34 + w45;
  w45 = w45 * w23;
  w44 = w44 + w45;
  w45 = w39 * w44;
  w46 = w12 * w18;
  w47 = w45 - w46;
  w48 = w18 * w47;
  w9 = w9 + w48;
  w48 = w40 * w34;
  w19 = w19 * w30;
  w48 = w48 - w19;
  w48 = w21 * w48;
  w48 = w48 * w23;
  w19 = w48 * w39;
  w9 = w9 - w19;
  w19 = w16 * w24;
  w49 = w27 * w21;
  w49 = w16 + w49;
  w49 = w49 * w23;
  w19 = w19 + w49;
  w49 = w12 * w19;
  w50 = w14 * w44;
  w51 = w49 - w50;
  w52 = w19 * w51;
  w9 = w9 - w52;
  w33 = w33 - w9;
  w9 = arg7[5];
  w29 = w29 * w9;
  w52 = w42 * w41;
  w29 = w29 - w52;
  w52 = w29 * w9;
  w33 = w33 - w52;
  w33 = w7 * w33;
  w42 = w42 * w35;
  w37 = w37 * w9;
  w42 = w42 - w37;
  w37 = w42 * w9;
  w4 = w4 * w13;
  w8 = w8 * w2;
  w4 = w4 + w8;
  w10 = w10 * w25;
  w4 = w4 + w10;
  w10 = w16 * w4;
  w25 = w34 * w22;
  w10 = w10 - w25;
  w25 = w10 * w24;
  w26 = w26 * w30;
  w38 = w38 * w16;
  w8 = w26 - w38;
  w2 = w16 * w8;
  w10 = w10 + w2;
  w6 = w34 * w6;
  w10 = w10 - w6;
  w10 = w10 * w23;
  w25 = w25 + w10;
  w48 = w48 * w12;
  w25 = w25 + w48;
  w48 = w14 * w18;
  w10 = w39 * w19;
  w6 = w48 - w10;
  w19 = w19 * w6;
  w25 = w25 + w19;
  w27 = w27 * w30;
  w40 = w40 * w16;
  w27 = w27 - w40;
  w21 = w21 * w27;
  w21 = w21 * w23;
  w14 = w21 * w14;
  w25 = w25 - w14;
  w47 = w44 * w47;
  w25 = w25 - w47;
  w37 = w37 - w25;
  w25 = w28 * w41;
  w37 = w37 - w25;
  w37 = w15 * w37;
  w33 = w33 + w37;
  w37 = w29 * w41;
  w25 = w34 * w11;
  w47 = w30 * w4;
  w25 = w25 - w47;
  w47 = w25 * w24;
  w34 = w34 * w1;
  w25 = w25 + w34;
  w30 = w30 * w8;
  w25 = w25 - w30;
  w25 = w25 * w23;
  w47 = w47 + w25;
  w21 = w21 * w39;
  w47 = w47 + w21;
  w44 = w44 * w51;
  w47 = w47 + w44;
  w20 = w20 * w12;
  w47 = w47 - w20;
  w18 = w18 * w6;
  w47 = w47 - w18;
  w37 = w37 - w47;
  w47 = w42 * w35;
  w37 = w37 - w47;
  w37 = w17 * w37;
  w33 = w33 + w37;
  w37 = w7 * w9;
  w47 = w17 * w41;
  w37 = w37 - w47;
  w47 = arg7[1];
  w29 = w29 + w47;
  w47 = w24 * w11;
  w11 = w11 + w32;
  w11 = w11 - w0;
  w11 = w23 * w11;
  w47 = w47 + w11;
  w47 = w47 + w49;
  w47 = w47 - w50;
  w29 = w29 - w47;
  w37 = w37 * w29;
  w33 = w33 + w37;
  w41 = w15 * w41;
  w7 = w7 * w35;
  w41 = w41 - w7;
  w7 = arg7[2];
  w28 = w28 + w7;
  w7 = w24 * w22;
  w22 = w22 + w3;
  w22 = w22 - w5;
  w22 = w23 * w22;
  w7 = w7 + w22;
  w7 = w7 + w45;
  w7 = w7 - w46;
  w28 = w28 - w7;
  w41 = w41 * w28;
  w33 = w33 + w41;
  w17 = w17 * w35;
  w15 = w15 * w9;
  w17 = w17 - w15;
  w15 = arg7[0];
  w42 = w42 + w15;
  w24 = w24 * w4;
  w4 = w4 + w26;
  w4 = w4 - w38;
  w23 = w23 * w4;
  w24 = w24 + w23;
  w24 = w24 + w48;
  w24 = w24 - w10;
  w42 = w42 - w24;
  w17 = w17 * w42;
  w33 = w33 + w17;
  res2[0] = w33;
  res3[0] = w31;
  res3[1] = w43;
  res3[2] = w36;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_contact_row(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[8];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 54);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 8; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && arg[4] && arg[5] && arg[6] && arg[7] && res[0] && res[1] && res[2] && res[3]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_contact_row_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 1, per = 16;
    casadi_real ang[16], ca[16], sa[16];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 16; ++k) ang[k] = 0;
    for (i0 = 0; i0 < n; i0 += per) {
      m = n - i0 < per ? n - i0 : per;
      large = 0;
      for (i = 0; i < m; ++i) {
        const casadi_real* q = arg[0] + (i0 + i) * stride[0] + 7;
        for (k = 0; k < na; ++k) {
          ang[i * na + k] = q[k];
          large |= !(fabs(q[k]) <= SNAKECG_SINCOS_MAX);
        }
      }
      for (k = 0; k < m * na; k += SNAKECG_SINCOS_BLOCK) {
        snakecg_sincos_block(ang + k, ca + k, sa + k);
      }
      if (large) snakecg_sincos_large(ang, ca, sa, m * na);
      for (i = 0; i < m; ++i) {
        snakecg_sp1_contact_row_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], arg[4] + (i0 + i) * stride[4], arg[5] + (i0 + i) * stride[5], arg[6] + (i0 + i) * stride[6], arg[7] + (i0 + i) * stride[7], ca + i * na, sa + i * na, res[0] + (i0 + i) * 7, res[1] + (i0 + i) * 6, res[2] + (i0 + i) * 1, res[3] + (i0 + i) * 3);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      a[4] = arg[4] + i * stride[4];
      a[5] = arg[5] + i * stride[5];
      a[6] = arg[6] + i * stride[6];
      a[7] = arg[7] + i * stride[7];
      r[0] = res[0] + i * 7;
      r[1] = res[1] + i * 6;
      r[2] = res[2] + i * 1;
      r[3] = res[3] + i * 3;
      if (snakecg_sp1_contact_row(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
