/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_poses() of
 * generated/spatial/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 82d64716a2089350522ee6ce607152c94df1120870c00e7b42763fcf4d7df073
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp3_link_poses_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_link_poses_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {169, 1, 1};
static const casadi_int casadi_s2[3] = {3, 4, 1};
static const casadi_int casadi_s3[3] = {3, 12, 1};

/* snakecg_sp3_link_poses:(q[10],K[169])->(position[3x4],rotation[3x12]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=1.;
  a04=-2.;
  a05=arg[0]? arg[0][4] : 0;
  a06=casadi_sq(a05);
  a06=(a04*a06);
  a07=(a03+a06);
  a08=arg[0]? arg[0][5] : 0;
  a09=casadi_sq(a08);
  a09=(a04*a09);
  a07=(a07+a09);
  a10=arg[1]? arg[1][124] : 0;
  a11=(a07*a10);
  a12=arg[0]? arg[0][6] : 0;
  a13=(a04*a12);
  a14=(a13*a08);
  a15=arg[0]? arg[0][3] : 0;
  a16=(2.*a15);
  a17=(a16*a05);
  a14=(a14+a17);
  a18=arg[1]? arg[1][125] : 0;
  a19=(a14*a18);
  a11=(a11+a19);
  a12=(2.*a12);
  a19=(a12*a05);
  a16=(a16*a08);
  a19=(a19+a16);
  a20=arg[1]? arg[1][126] : 0;
  a21=(a19*a20);
  a11=(a11+a21);
  a11=(a11+a00);
  if (res[0]!=0) res[0][3]=a11;
  a00=(a12*a08);
  a00=(a00+a17);
  a17=(a00*a10);
  a21=casadi_sq(a15);
  a04=(a04*a21);
  a03=(a03+a04);
  a09=(a03+a09);
  a04=(a09*a18);
  a17=(a17+a04);
  a04=(a13*a15);
  a21=(2.*a05);
  a21=(a21*a08);
  a04=(a04+a21);
  a08=(a04*a20);
  a17=(a17+a08);
  a17=(a17+a01);
  if (res[0]!=0) res[0][4]=a17;
  a13=(a13*a05);
  a13=(a13+a16);
  a10=(a13*a10);
  a12=(a12*a15);
  a12=(a12+a21);
  a18=(a12*a18);
  a10=(a10+a18);
  a03=(a03+a06);
  a20=(a03*a20);
  a10=(a10+a20);
  a10=(a10+a02);
  if (res[0]!=0) res[0][5]=a10;
  a02=arg[1]? arg[1][103] : 0;
  a20=(a02*a07);
  a06=arg[1]? arg[1][104] : 0;
  a18=(a06*a14);
  a20=(a20+a18);
  a18=arg[1]? arg[1][105] : 0;
  a21=(a18*a19);
  a20=(a20+a21);
  a21=arg[1]? arg[1][129] : 0;
  a15=(a20*a21);
  a16=arg[1]? arg[1][97] : 0;
  a05=(a16*a07);
  a01=arg[1]? arg[1][98] : 0;
  a08=(a01*a14);
  a05=(a05+a08);
  a08=arg[1]? arg[1][99] : 0;
  a22=(a08*a19);
  a05=(a05+a22);
  a22=arg[0]? arg[0][7] : 0;
  a23=cos(a22);
  a24=(a05*a23);
  a25=arg[1]? arg[1][100] : 0;
  a26=(a25*a07);
  a27=arg[1]? arg[1][101] : 0;
  a28=(a27*a14);
  a26=(a26+a28);
  a28=arg[1]? arg[1][102] : 0;
  a29=(a28*a19);
  a26=(a26+a29);
  a22=sin(a22);
  a29=(a26*a22);
  a24=(a24+a29);
  a29=arg[1]? arg[1][127] : 0;
  a30=(a24*a29);
  a15=(a15+a30);
  a26=(a26*a23);
  a05=(a05*a22);
  a26=(a26-a05);
  a05=arg[1]? arg[1][128] : 0;
  a30=(a26*a05);
  a15=(a15+a30);
  a15=(a15+a11);
  if (res[0]!=0) res[0][6]=a15;
  a11=(a02*a00);
  a30=(a06*a09);
  a11=(a11+a30);
  a30=(a18*a04);
  a11=(a11+a30);
  a30=(a11*a21);
  a31=(a16*a00);
  a32=(a01*a09);
  a31=(a31+a32);
  a32=(a08*a04);
  a31=(a31+a32);
  a32=(a31*a23);
  a33=(a25*a00);
  a34=(a27*a09);
  a33=(a33+a34);
  a34=(a28*a04);
  a33=(a33+a34);
  a34=(a33*a22);
  a32=(a32+a34);
  a34=(a32*a29);
  a30=(a30+a34);
  a33=(a33*a23);
  a31=(a31*a22);
  a33=(a33-a31);
  a31=(a33*a05);
  a30=(a30+a31);
  a30=(a30+a17);
  if (res[0]!=0) res[0][7]=a30;
  a02=(a02*a13);
  a06=(a06*a12);
  a02=(a02+a06);
  a18=(a18*a03);
  a02=(a02+a18);
  a21=(a02*a21);
  a16=(a16*a13);
  a01=(a01*a12);
  a16=(a16+a01);
  a08=(a08*a03);
  a16=(a16+a08);
  a08=(a16*a23);
  a25=(a25*a13);
  a27=(a27*a12);
  a25=(a25+a27);
  a28=(a28*a03);
  a25=(a25+a28);
  a28=(a25*a22);
  a08=(a08+a28);
  a29=(a08*a29);
  a21=(a21+a29);
  a25=(a25*a23);
  a16=(a16*a22);
  a25=(a25-a16);
  a05=(a25*a05);
  a21=(a21+a05);
  a21=(a21+a10);
  if (res[0]!=0) res[0][8]=a21;
  a10=arg[1]? arg[1][114] : 0;
  a05=(a20*a10);
  a16=arg[1]? arg[1][112] : 0;
  a22=(a16*a24);
  a05=(a05+a22);
  a22=arg[1]? arg[1][113] : 0;
  a23=(a22*a26);
  a05=(a05+a23);
  a23=arg[1]? arg[1][132] : 0;
  a29=(a05*a23);
  a28=arg[1]? arg[1][108] : 0;
  a27=(a20*a28);
  a01=arg[1]? arg[1][106] : 0;
  a18=(a01*a24);
  a27=(a27+a18);
  a18=arg[1]? arg[1][107] : 0;
  a06=(a18*a26);
  a27=(a27+a06);
  a06=arg[0]? arg[0][8] : 0;
  a17=cos(a06);
  a31=(a27*a17);
  a34=arg[1]? arg[1][111] : 0;
  a35=(a20*a34);
  a36=arg[1]? arg[1][109] : 0;
  a37=(a36*a24);
  a35=(a35+a37);
  a37=arg[1]? arg[1][110] : 0;
  a38=(a37*a26);
  a35=(a35+a38);
  a06=sin(a06);
  a38=(a35*a06);
  a31=(a31+a38);
  a38=arg[1]? arg[1][130] : 0;
  a39=(a31*a38);
  a29=(a29+a39);
  a35=(a35*a17);
  a27=(a27*a06);
  a35=(a35-a27);
  a27=arg[1]? arg[1][131] : 0;
  a39=(a35*a27);
  a29=(a29+a39);
  a29=(a29+a15);
  if (res[0]!=0) res[0][9]=a29;
  a29=(a11*a10);
  a15=(a16*a32);
  a29=(a29+a15);
  a15=(a22*a33);
  a29=(a29+a15);
  a15=(a29*a23);
  a39=(a11*a28);
  a40=(a01*a32);
  a39=(a39+a40);
  a40=(a18*a33);
  a39=(a39+a40);
  a40=(a39*a17);
  a41=(a11*a34);
  a42=(a36*a32);
  a41=(a41+a42);
  a42=(a37*a33);
  a41=(a41+a42);
  a42=(a41*a06);
  a40=(a40+a42);
  a42=(a40*a38);
  a15=(a15+a42);
  a41=(a41*a17);
  a39=(a39*a06);
  a41=(a41-a39);
  a39=(a41*a27);
  a15=(a15+a39);
  a15=(a15+a30);
  if (res[0]!=0) res[0][10]=a15;
  a10=(a02*a10);
  a16=(a16*a08);
  a10=(a10+a16);
  a22=(a22*a25);
  a10=(a10+a22);
  a23=(a10*a23);
  a28=(a02*a28);
  a01=(a01*a08);
  a28=(a28+a01);
  a18=(a18*a25);
  a28=(a28+a18);
  a18=(a28*a17);
  a34=(a02*a34);
  a36=(a36*a08);
  a34=(a34+a36);
  a37=(a37*a25);
  a34=(a34+a37);
  a37=(a34*a06);
  a18=(a18+a37);
  a38=(a18*a38);
  a23=(a23+a38);
  a34=(a34*a17);
  a28=(a28*a06);
  a34=(a34-a28);
  a27=(a34*a27);
  a23=(a23+a27);
  a23=(a23+a21);
  if (res[0]!=0) res[0][11]=a23;
  if (res[1]!=0) res[1][0]=a07;
  if (res[1]!=0) res[1][1]=a00;
  if (res[1]!=0) res[1][2]=a13;
  if (res[1]!=0) res[1][3]=a14;
  if (res[1]!=0) res[1][4]=a09;
  if (res[1]!=0) res[1][5]=a12;
  if (res[1]!=0) res[1][6]=a19;
  if (res[1]!=0) res[1][7]=a04;
  if (res[1]!=0) res[1][8]=a03;
  a03=arg[1]? arg[1][76] : 0;
  a04=(a20*a03);
  a19=arg[1]? arg[1][70] : 0;
  a12=(a19*a24);
  a04=(a04+a12);
  a12=arg[1]? arg[1][73] : 0;
  a09=(a12*a26);
  a04=(a04+a09);
  if (res[1]!=0) res[1][9]=a04;
  a04=(a11*a03);
  a09=(a19*a32);
  a04=(a04+a09);
  a09=(a12*a33);
  a04=(a04+a09);
  if (res[1]!=0) res[1][10]=a04;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a12=(a12*a25);
  a03=(a03+a12);
  if (res[1]!=0) res[1][11]=a03;
  a03=arg[1]? arg[1][77] : 0;
  a12=(a20*a03);
  a19=arg[1]? arg[1][71] : 0;
  a04=(a19*a24);
  a12=(a12+a04);
  a04=arg[1]? arg[1][74] : 0;
  a09=(a04*a26);
  a12=(a12+a09);
  if (res[1]!=0) res[1][12]=a12;
  a12=(a11*a03);
  a09=(a19*a32);
  a12=(a12+a09);
  a09=(a04*a33);
  a12=(a12+a09);
  if (res[1]!=0) res[1][13]=a12;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a04=(a04*a25);
  a03=(a03+a04);
  if (res[1]!=0) res[1][14]=a03;
  a03=arg[1]? arg[1][78] : 0;
  a20=(a20*a03);
  a04=arg[1]? arg[1][72] : 0;
  a24=(a04*a24);
  a20=(a20+a24);
  a24=arg[1]? arg[1][75] : 0;
  a26=(a24*a26);
  a20=(a20+a26);
  if (res[1]!=0) res[1][15]=a20;
  a11=(a11*a03);
  a32=(a04*a32);
  a11=(a11+a32);
  a33=(a24*a33);
  a11=(a11+a33);
  if (res[1]!=0) res[1][16]=a11;
  a02=(a02*a03);
  a04=(a04*a08);
  a02=(a02+a04);
  a24=(a24*a25);
  a02=(a02+a24);
  if (res[1]!=0) res[1][17]=a02;
  a02=arg[1]? arg[1][85] : 0;
  a24=(a05*a02);
  a25=arg[1]? arg[1][79] : 0;
  a04=(a25*a31);
  a24=(a24+a04);
  a04=arg[1]? arg[1][82] : 0;
  a08=(a04*a35);
  a24=(a24+a08);
  if (res[1]!=0) res[1][18]=a24;
  a24=(a29*a02);
  a08=(a25*a40);
  a24=(a24+a08);
  a08=(a04*a41);
  a24=(a24+a08);
  if (res[1]!=0) res[1][19]=a24;
  a02=(a10*a02);
  a25=(a25*a18);
  a02=(a02+a25);
  a04=(a04*a34);
  a02=(a02+a04);
  if (res[1]!=0) res[1][20]=a02;
  a02=arg[1]? arg[1][86] : 0;
  a04=(a05*a02);
  a25=arg[1]? arg[1][80] : 0;
  a24=(a25*a31);
  a04=(a04+a24);
  a24=arg[1]? arg[1][83] : 0;
  a08=(a24*a35);
  a04=(a04+a08);
  if (res[1]!=0) res[1][21]=a04;
  a04=(a29*a02);
  a08=(a25*a40);
  a04=(a04+a08);
  a08=(a24*a41);
  a04=(a04+a08);
  if (res[1]!=0) res[1][22]=a04;
  a02=(a10*a02);
  a25=(a25*a18);
  a02=(a02+a25);
  a24=(a24*a34);
  a02=(a02+a24);
  if (res[1]!=0) res[1][23]=a02;
  a02=arg[1]? arg[1][87] : 0;
  a24=(a05*a02);
  a25=arg[1]? arg[1][81] : 0;
  a04=(a25*a31);
  a24=(a24+a04);
  a04=arg[1]? arg[1][84] : 0;
  a08=(a04*a35);
  a24=(a24+a08);
  if (res[1]!=0) res[1][24]=a24;
  a24=(a29*a02);
  a08=(a25*a40);
  a24=(a24+a08);
  a08=(a04*a41);
  a24=(a24+a08);
  if (res[1]!=0) res[1][25]=a24;
  a02=(a10*a02);
  a25=(a25*a18);
  a02=(a02+a25);
  a04=(a04*a34);
  a02=(a02+a04);
  if (res[1]!=0) res[1][26]=a02;
  a02=arg[1]? arg[1][123] : 0;
  a04=(a05*a02);
  a25=arg[1]? arg[1][121] : 0;
  a24=(a25*a31);
  a04=(a04+a24);
  a24=arg[1]? arg[1][122] : 0;
  a08=(a24*a35);
  a04=(a04+a08);
  a08=arg[1]? arg[1][94] : 0;
  a03=(a04*a08);
  a11=arg[1]? arg[1][88] : 0;
  a33=arg[1]? arg[1][117] : 0;
  a32=(a05*a33);
  a20=arg[1]? arg[1][115] : 0;
  a26=(a20*a31);
  a32=(a32+a26);
  a26=arg[1]? arg[1][116] : 0;
  a19=(a26*a35);
  a32=(a32+a19);
  a19=arg[0]? arg[0][9] : 0;
  a12=cos(a19);
  a09=(a32*a12);
  a14=arg[1]? arg[1][120] : 0;
  a05=(a05*a14);
  a13=arg[1]? arg[1][118] : 0;
  a31=(a13*a31);
  a05=(a05+a31);
  a31=arg[1]? arg[1][119] : 0;
  a35=(a31*a35);
  a05=(a05+a35);
  a19=sin(a19);
  a35=(a05*a19);
  a09=(a09+a35);
  a35=(a11*a09);
  a03=(a03+a35);
  a35=arg[1]? arg[1][91] : 0;
  a05=(a05*a12);
  a32=(a32*a19);
  a05=(a05-a32);
  a32=(a35*a05);
  a03=(a03+a32);
  if (res[1]!=0) res[1][27]=a03;
  a03=(a29*a02);
  a32=(a25*a40);
  a03=(a03+a32);
  a32=(a24*a41);
  a03=(a03+a32);
  a32=(a03*a08);
  a00=(a29*a33);
  a07=(a20*a40);
  a00=(a00+a07);
  a07=(a26*a41);
  a00=(a00+a07);
  a07=(a00*a12);
  a29=(a29*a14);
  a40=(a13*a40);
  a29=(a29+a40);
  a41=(a31*a41);
  a29=(a29+a41);
  a41=(a29*a19);
  a07=(a07+a41);
  a41=(a11*a07);
  a32=(a32+a41);
  a29=(a29*a12);
  a00=(a00*a19);
  a29=(a29-a00);
  a00=(a35*a29);
  a32=(a32+a00);
  if (res[1]!=0) res[1][28]=a32;
  a02=(a10*a02);
  a25=(a25*a18);
  a02=(a02+a25);
  a24=(a24*a34);
  a02=(a02+a24);
  a08=(a02*a08);
  a33=(a10*a33);
  a20=(a20*a18);
  a33=(a33+a20);
  a26=(a26*a34);
  a33=(a33+a26);
  a26=(a33*a12);
  a10=(a10*a14);
  a13=(a13*a18);
  a10=(a10+a13);
  a31=(a31*a34);
  a10=(a10+a31);
  a31=(a10*a19);
  a26=(a26+a31);
  a11=(a11*a26);
  a08=(a08+a11);
  a10=(a10*a12);
  a33=(a33*a19);
  a10=(a10-a33);
  a35=(a35*a10);
  a08=(a08+a35);
  if (res[1]!=0) res[1][29]=a08;
  a08=arg[1]? arg[1][95] : 0;
  a35=(a04*a08);
  a33=arg[1]? arg[1][89] : 0;
  a19=(a33*a09);
  a35=(a35+a19);
  a19=arg[1]? arg[1][92] : 0;
  a12=(a19*a05);
  a35=(a35+a12);
  if (res[1]!=0) res[1][30]=a35;
  a35=(a03*a08);
  a12=(a33*a07);
  a35=(a35+a12);
  a12=(a19*a29);
  a35=(a35+a12);
  if (res[1]!=0) res[1][31]=a35;
  a08=(a02*a08);
  a33=(a33*a26);
  a08=(a08+a33);
  a19=(a19*a10);
  a08=(a08+a19);
  if (res[1]!=0) res[1][32]=a08;
  a08=arg[1]? arg[1][96] : 0;
  a04=(a04*a08);
  a19=arg[1]? arg[1][90] : 0;
  a09=(a19*a09);
  a04=(a04+a09);
  a09=arg[1]? arg[1][93] : 0;
  a05=(a09*a05);
  a04=(a04+a05);
  if (res[1]!=0) res[1][33]=a04;
  a03=(a03*a08);
  a07=(a19*a07);
  a03=(a03+a07);
  a29=(a09*a29);
  a03=(a03+a29);
  if (res[1]!=0) res[1][34]=a03;
  a02=(a02*a08);
  a19=(a19*a26);
  a02=(a02+a19);
  a09=(a09*a10);
  a02=(a02+a09);
  if (res[1]!=0) res[1][35]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_poses_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_poses_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_poses_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_poses_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_poses_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_link_poses_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_poses_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_poses_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "rotation";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_poses_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_poses_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_poses_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

/* snakecg_sp3_link_poses_sincos: 534 CasADi instructions, printed one per line */
static void snakecg_sp3_link_poses_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0,
    casadi_real* restrict res1) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42;
  w0 = arg0[0];
  res0[0] = w0;
  w1 = arg0[1];
  res0[1] = w1;
  w2 = arg0[2];
  res0[2] = w2;
  w3 = 1.0;
  w4 = (-2.0);
  w5 = arg0[4];
  w6 = w5 * w5;
  w6 = w4 * w6;
  w7 = w3 + w6;
  w8 = arg0[5];
  w9 = w8 * w8;
  w9 = w4 * w9;
  w7 = w7 + w9;
  w10 = arg1[124];
  w11 = w7 * w10;
  w12 = arg0[6];
  w13 = w4 * w12;
  w14 = w13 * w8;
  w15 = arg0[3];
  w16 = w15 + w15;
  w17 = w16 * w5;
  w14 = w14 + w17;
  w18 = arg1[125];
  w19 = w14 * w18;
  w11 = w11 + w19;
  w12 = w12 + w12;
  w19 = w12 * w5;
  w16 = w16 * w8;
  w19 = w19 + w16;
  w20 = arg1[126];
  w21 = w19 * w20;
  w11 = w11 + w21;
  w11 = w11 + w0;
  res0[3] = w11;
  w0 = w12 * w8;
  w0 = w0 + w17;
  w17 = w0 * w10;
  w21 = w15 * w15;
  w4 = w4 * w21;
  w3 = w3 + w4;
  w9 = w3 + w9;
  w4 = w9 * w18;
  w17 = w17 + w4;
  w4 = w13 * w15;
  w21 = w5 + w5;
  w21 = w21 * w8;
  w4 = w4 + w21;
  w8 = w4 * w20;
  w17 = w17 + w8;
  w17 = w17 + w1;
  res0[4] = w17;
  w13 = w13 * w5;
  w13 = w13 + w16;
  w10 = w13 * w10;
  w12 = w12 * w15;
  w12 = w12 + w21;
  w18 = w12 * w18;
  w10 = w10 + w18;
  w3 = w3 + w6;
  w20 = w3 * w20;
  w10 = w10 + w20;
  w10 = w10 + w2;
  res0[5] = w10;
  w2 = arg1[103];
  w20 = w2 * w7;
  w6 = arg1[104];
  w18 = w6 * w14;
  w20 = w20 + w18;
  w18 = arg1[105];
  w21 = w18 * w19;
  w20 = w20 + w21;
  w21 = arg1[129];
  w15 = w20 * w21;
  w16 = arg1[97];
  w5 = w16 * w7;
  w1 = arg1[98];
  w8 = w1 * w14;
  w5 = w5 + w8;
  w8 = arg1[99];
  w22 = w8 * w19;
  w5 = w5 + w22;
  w22 = arg2[0];
  w23 = w5 * w22;
  w24 = arg1[100];
  w25 = w24 * w7;
  w26 = arg1[101];
  w27 = w26 * w14;
  w25 = w25 + w27;
  w27 = arg1[102];
  w28 = w27 * w19;
  w25 = w25 + w28;
  w28 = arg3[0];
  w29 = w25 * w28;
  w23 = w23 + w29;
  w29 = arg1[127];
  w30 = w23 * w29;
  w15 = w15 + w30;
  w25 = w25 * w22;
  w5 = w5 * w28;
  w25 = w25 - w5;
  w5 = arg1[128];
  w30 = w25 * w5;
  w15 = w15 + w30;
  w15 = w15 + w11;
  res0[6] = w15;
  w11 = w2 * w0;
  w30 = w6 * w9;
  w11 = w11 + w30;
  w30 = w18 * w4;
  w11 = w11 + w30;
  w30 = w11 * w21;
  w31 = w16 * w0;
  w32 = w1 * w9;
  w31 = w31 + w32;
  w32 = w8 * w4;
  w31 = w31 + w32;
  w32 = w31 * w22;
  w33 = w24 * w0;
  w34 = w26 * w9;
  w33 = w33 + w34;
  w34 = w27 * w4;
  w33 = w33 + w34;
  w34 = w33 * w28;
  w32 = w32 + w34;
  w34 = w32 * w29;
  w30 = w30 + w34;
  w33 = w33 * w22;
  w31 = w31 * w28;
  w33 = w33 - w31;
  w31 = w33 * w5;
  w30 = w30 + w31;
  w30 = w30 + w17;
  res0[7] = w30;
  w2 = w2 * w13;
  w6 = w6 * w12;
  w2 = w2 + w6;
  w18 = w18 * w3;
  w2 = w2 + w18;
  w21 = w2 * w21;
  w16 = w16 * w13;
  w1 = w1 * w12;
  w16 = w16 + w1;
  w8 = w8 * w3;
  w16 = w16 + w8;
  w8 = w16 * w22;
  w24 = w24 * w13;
  w26 = w26 * w12;
  w24 = w24 + w26;
  w27 = w27 * w3;
  w24 = w24 + w27;
  w27 = w24 * w28;
  w8 = w8 + w27;
  w29 = w8 * w29;
  w21 = w21 + w29;
  w24 = w24 * w22;
  w16 = w16 * w28;
  w24 = w24 - w16;
  w5 = w24 * w5;
  w21 = w21 + w5;
  w21 = w21 + w10;
  res0[8] = w21;
  w10 = arg1[114];
  w5 = w20 * w10;
  w16 = arg1[112];
  w28 = w16 * w23;
  w5 = w5 + w28;
  w28 = arg1[113];
  w22 = w28 * w25;
  w5 = w5 + w22;
  w22 = arg1[132];
  w29 = w5 * w22;
  w27 = arg1[108];
  w26 = w20 * w27;
  w1 = arg1[106];
  w18 = w1 * w23;
  w26 = w26 + w18;
  w18 = arg1[107];
  w6 = w18 * w25;
  w26 = w26 + w6;
  w6 = arg2[1];
  w17 = w26 * w6;
  w31 = arg1[111];
  w34 = w20 * w31;
  w35 = arg1[109];
  w36 = w35 * w23;
  w34 = w34 + w36;
  w36 = arg1[110];
  w37 = w36 * w25;
  w34 = w34 + w37;
  w37 = arg3[1];
  w38 = w34 * w37;
  w17 = w17 + w38;
  w38 = arg1[130];
  w39 = w17 * w38;
  w29 = w29 + w39;
  w34 = w34 * w6;
  w26 = w26 * w37;
  w34 = w34 - w26;
  w26 = arg1[131];
  w39 = w34 * w26;
  w29 = w29 + w39;
  w29 = w29 + w15;
  res0[9] = w29;
  w29 = w11 * w10;
  w15 = w16 * w32;
  w29 = w29 + w15;
  w15 = w28 * w33;
  w29 = w29 + w15;
  w15 = w29 * w22;
  w39 = w11 * w27;
  w40 = w1 * w32;
  w39 = w39 + w40;
  w40 = w18 * w33;
  w39 = w39 + w40;
  w40 = w39 * w6;
  w41 = w11 * w31;
  w42 = w35 * w32;
  w41 = w41 + w42;
  w42 = w36 * w33;
  w41 = w41 + w42;
  w42 = w41 * w37;
  w40 = w40 + w42;
  w42 = w40 * w38;
  w15 = w15 + w42;
  w41 = w41 * w6;
  w39 = w39 * w37;
  w41 = w41 - w39;
  w39 = w41 * w26;
  w15 = w15 + w39;
  w15 = w15 + w30;
  res0[10] = w15;
  w10 = w2 * w10;
  w16 = w16 * w8;
  w10 = w10 + w16;
  w28 = w28 * w24;
  w10 = w10 + w28;
  w22 = w10 * w22;
  w27 = w2 * w27;
  w1 = w1 * w8;
  w27 = w27 + w1;
  w18 = w18 * w24;
  w27 = w27 + w18;
  w18 = w27 * w6;
  w31 = w2 * w31;
  w35 = w35 * w8;
  w31 = w31 + w35;
  w36 = w36 * w24;
  w31 = w31 + w36;
  w36 = w31 * w37;
  w18 = w18 + w36;
  w38 = w18 * w38;
  w22 = w22 + w38;
  w31 = w31 * w6;
  w27 = w27 * w37;
  w31 = w31 - w27;
  w26 = w31 * w26;
  w22 = w22 + w26;
  w22 = w22 + w21;
  res0[11] = w22;
  res1[0] = w7;
  res1[1] = w0;
  res1[2] = w13;
  res1[3] = w14;
  res1[4] = w9;
  res1[5] = w12;
  res1[6] = w19;
  res1[7] = w4;
  res1[8] = w3;
  w3 = arg1[76];
  w4 = w20 * w3;
  w19 = arg1[70];
  w12 = w19 * w23;
  w4 = w4 + w12;
  w12 = arg1[73];
  w9 = w12 * w25;
  w4 = w4 + w9;
  res1[9] = w4;
  w4 = w11 * w3;
  w9 = w19 * w32;
  w4 = w4 + w9;
  w9 = w12 * w33;
  w4 = w4 + w9;
  res1[10] = w4;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w12 = w12 * w24;
  w3 = w3 + w12;
  res1[11] = w3;
  w3 = arg1[77];
  w12 = w20 * w3;
  w19 = arg1[71];
  w4 = w19 * w23;
  w12 = w12 + w4;
  w4 = arg1[74];
  w9 = w4 * w25;
  w12 = w12 + w9;
  res1[12] = w12;
  w12 = w11 * w3;
  w9 = w19 * w32;
  w12 = w12 + w9;
  w9 = w4 * w33;
  w12 = w12 + w9;
  res1[13] = w12;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w4 = w4 * w24;
  w3 = w3 + w4;
  res1[14] = w3;
  w3 = arg1[78];
  w20 = w20 * w3;
  w4 = arg1[72];
  w23 = w4 * w23;
  w20 = w20 + w23;
  w23 = arg1[75];
  w25 = w23 * w25;
  w20 = w20 + w25;
  res1[15] = w20;
  w11 = w11 * w3;
  w32 = w4 * w32;
  w11 = w11 + w32;
  w33 = w23 * w33;
  w11 = w11 + w33;
  res1[16] = w11;
  w2 = w2 * w3;
  w4 = w4 * w8;
  w2 = w2 + w4;
  w23 = w23 * w24;
  w2 = w2 + w23;
  res1[17] = w2;
  w2 = arg1[85];
  w23 = w5 * w2;
  w24 = arg1[79];
  w4 = w24 * w17;
  w23 = w23 + w4;
  w4 = arg1[82];
  w8 = w4 * w34;
  w23 = w23 + w8;
  res1[18] = w23;
  w23 = w29 * w2;
  w8 = w24 * w40;
  w23 = w23 + w8;
  w8 = w4 * w41;
  w23 = w23 + w8;
  res1[19] = w23;
  w2 = w10 * w2;
  w24 = w24 * w18;
  w2 = w2 + w24;
  w4 = w4 * w31;
  w2 = w2 + w4;
  res1[20] = w2;
  w2 = arg1[86];
  w4 = w5 * w2;
  w24 = arg1[80];
  w23 = w24 * w17;
  w4 = w4 + w23;
  w23 = arg1[83];
  w8 = w23 * w34;
  w4 = w4 + w8;
  res1[21] = w4;
  w4 = w29 * w2;
  w8 = w24 * w40;
  w4 = w4 + w8;
  w8 = w23 * w41;
  w4 = w4 + w8;
  res1[22] = w4;
  w2 = w10 * w2;
  w24 = w24 * w18;
  w2 = w2 + w24;
  w23 = w23 * w31;
  w2 = w2 + w23;
  res1[23] = w2;
  w2 = arg1[87];
  w23 = w5 * w2;
  w24 = arg1[81];
  w4 = w24 * w17;
  w23 = w23 + w4;
  w4 = arg1[84];
  w8 = w4 * w34;
  w23 = w23 + w8;
  res1[24] = w23;
  w23 = w29 * w2;
  w8 = w24 * w40;
  w23 = w23 + w8;
  w8 = w4 * w41;
  w23 = w23 + w8;
  res1[25] = w23;
  w2 = w10 * w2;
  w24 = w24 * w18;
  w2 = w2 + w24;
  w4 = w4 * w31;
  w2 = w2 + w4;
  res1[26] = w2;
  w2 = arg1[123];
  w4 = w5 * w2;
  w24 = arg1[121];
  w23 = w24 * w17;
  w4 = w4 + w23;
  w23 = arg1[122];
  w8 = w23 * w34;
  w4 = w4 + w8;
  w8 = arg1[94];
  w3 = w4 * w8;
  w11 = arg1[88];
  w33 = arg1[117];
  w32 = w5 * w33;
  w20 = arg1[115];
  w25 = w20 * w17;
  w32 = w32 + w25;
  w25 = arg1[116];
  w19 = w25 * w34;
  w32 = w32 + w19;
  w19 = arg2[2];
  w12 = w32 * w19;
  w9 = arg1[120];
  w5 = w5 * w9;
  w14 = arg1[118];
  w17 = w14 * w17;
  w5 = w5 + w17;
  w17 = arg1[119];
  w34 = w17 * w34;
  w5 = w5 + w34;
  w34 = arg3[2];
  w13 = w5 * w34;
  w12 = w12 + w13;
  w13 = w11 * w12;
  w3 = w3 + w13;
  w13 = arg1[91];
  w5 = w5 * w19;
  w32 = w32 * w34;
  w5 = w5 - w32;
  w32 = w13 * w5;
  w3 = w3 + w32;
  res1[27] = w3;
  w3 = w29 * w2;
  w32 = w24 * w40;
  w3 = w3 + w32;
  w32 = w23 * w41;
  w3 = w3 + w32;
  w32 = w3 * w8;
  w0 = w29 * w33;
  w7 = w20 * w40;
  w0 = w0 + w7;
  w7 = w25 * w41;
  w0 = w0 + w7;
  w7 = w0 * w19;
  w29 = w29 * w9;
  w40 = w14 * w40;
  w29 = w29 + w40;
  w41 = w17 * w41;
  w29 = w29 + w41;
  w41 = w29 * w34;
  w7 = w7 + w41;
  w41 = w11 * w7;
  w32 = w32 + w41;
  w29 = w29 * w19;
  w0 = w0 * w34;
  w29 = w29 - w0;
  w0 = w13 * w29;
  w32 = w32 + w0;
  res1[28] = w32;
  w2 = w10 * w2;
  w24 = w24 * w18;
  w2 = w2 + w24;
  w23 = w23 * w31;
  w2 = w2 + w23;
  w8 = w2 * w8;
  w33 = w10 * w33;
  w20 = w20 * w18;
  w33 = w33 + w20;
  w25 = w25 * w31;
  w33 = w33 + w25;
  w25 = w33 * w19;
  w10 = w10 * w9;
  w14 = w14 * w18;
  w10 = w10 + w14;
  w17 = w17 * w31;
  w10 = w10 + w17;
  w17 = w10 * w34;
  w25 = w25 + w17;
  w11 = w11 * w25;
  w8 = w8 + w11;
  w10 = w10 * w19;
  w33 = w33 * w34;
  w10 = w10 - w33;
  w13 = w13 * w10;
  w8 = w8 + w13;
  res1[29] = w8;
  w8 = arg1[95];
  w13 = w4 * w8;
  w33 = arg1[89];
  w34 = w33 * w12;
  w13 = w13 + w34;
  w34 = arg1[92];
  w19 = w34 * w5;
  w13 = w13 + w19;
  res1[30] = w13;
  w13 = w3 * w8;
  w19 = w33 * w7;
  w13 = w13 + w19;
  w19 = w34 * w29;
  w13 = w13 + w19;
  res1[31] = w13;
  w8 = w2 * w8;
  w33 = w33 * w25;
  w8 = w8 + w33;
  w34 = w34 * w10;
  w8 = w8 + w34;
  res1[32] = w8;
  w8 = arg1[96];
  w4 = w4 * w8;
  w34 = arg1[90];
  w12 = w34 * w12;
  w4 = w4 + w12;
  w12 = arg1[93];
  w5 = w12 * w5;
  w4 = w4 + w5;
  res1[33] = w4;
  w3 = w3 * w8;
  w7 = w34 * w7;
  w3 = w3 + w7;
  w29 = w12 * w29;
  w3 = w3 + w29;
  res1[34] = w3;
  w2 = w2 * w8;
  w34 = w34 * w25;
  w2 = w2 + w34;
  w12 = w12 * w10;
  w2 = w2 + w12;
  res1[35] = w2;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_link_poses(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 44);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0] && res[1]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_link_poses_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 3, per = 16;
    casadi_real ang[48], ca[48], sa[48];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 48; ++k) ang[k] = 0;
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
        snakecg_sp3_link_poses_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 12, res[1] + (i0 + i) * 36);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 12;
      r[1] = res[1] + i * 36;
      if (snakecg_sp3_link_poses(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
