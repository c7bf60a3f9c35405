/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for scene_kinematics() of
 * generated/na5/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: a2d11c24d4176a7337125b71c8295163762d302b9468a78a7f172d9e0a64cce1
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na5_scene_kinematics_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na5_scene_kinematics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {58, 1, 1};
static const casadi_int casadi_s2[3] = {3, 6, 1};
static const casadi_int casadi_s3[3] = {18, 8, 1};
static const casadi_int casadi_s4[3] = {8, 8, 1};
static const casadi_int casadi_s5[3] = {2, 6, 1};

/* snakecg_na5_scene_kinematics:(q[8],K[58])->(poses[3x6],J[18x8],M[8x8],cs[2x6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][6] : 0;
  a05=arg[1]? arg[1][18] : 0;
  a04=(a04-a05);
  a05=(a03*a04);
  a06=(a05+a00);
  a07=arg[0]? arg[0][3] : 0;
  a08=cos(a07);
  a09=(a03*a08);
  a10=sin(a02);
  a11=sin(a07);
  a12=(a10*a11);
  a09=(a09-a12);
  a12=arg[1]? arg[1][19] : 0;
  a13=(a09*a12);
  a14=(a06+a13);
  if (res[0]!=0) res[0][3]=a14;
  a04=(a04*a10);
  a15=(a04+a01);
  a11=(a03*a11);
  a08=(a08*a10);
  a11=(a11+a08);
  a08=(a11*a12);
  a16=(a15+a08);
  if (res[0]!=0) res[0][4]=a16;
  a07=(a07+a02);
  if (res[0]!=0) res[0][5]=a07;
  a02=arg[1]? arg[1][7] : 0;
  a12=(a02-a12);
  a17=(a09*a12);
  a17=(a14+a17);
  a18=arg[0]? arg[0][4] : 0;
  a19=cos(a18);
  a20=(a09*a19);
  a21=sin(a18);
  a22=(a11*a21);
  a20=(a20-a22);
  a22=arg[1]? arg[1][20] : 0;
  a23=(a20*a22);
  a24=(a17+a23);
  if (res[0]!=0) res[0][6]=a24;
  a12=(a12*a11);
  a12=(a16+a12);
  a21=(a09*a21);
  a19=(a19*a11);
  a21=(a21+a19);
  a19=(a21*a22);
  a25=(a12+a19);
  if (res[0]!=0) res[0][7]=a25;
  a07=(a07+a18);
  if (res[0]!=0) res[0][8]=a07;
  a18=arg[1]? arg[1][8] : 0;
  a22=(a18-a22);
  a26=(a20*a22);
  a26=(a24+a26);
  a27=arg[0]? arg[0][5] : 0;
  a28=cos(a27);
  a29=(a20*a28);
  a30=sin(a27);
  a31=(a21*a30);
  a29=(a29-a31);
  a31=arg[1]? arg[1][21] : 0;
  a32=(a29*a31);
  a33=(a26+a32);
  if (res[0]!=0) res[0][9]=a33;
  a22=(a22*a21);
  a22=(a25+a22);
  a30=(a20*a30);
  a28=(a28*a21);
  a30=(a30+a28);
  a28=(a30*a31);
  a34=(a22+a28);
  if (res[0]!=0) res[0][10]=a34;
  a07=(a07+a27);
  if (res[0]!=0) res[0][11]=a07;
  a27=arg[1]? arg[1][9] : 0;
  a31=(a27-a31);
  a35=(a29*a31);
  a35=(a33+a35);
  a36=arg[0]? arg[0][6] : 0;
  a37=cos(a36);
  a38=(a29*a37);
  a39=sin(a36);
  a40=(a30*a39);
  a38=(a38-a40);
  a40=arg[1]? arg[1][22] : 0;
  a41=(a38*a40);
  a42=(a35+a41);
  if (res[0]!=0) res[0][12]=a42;
  a31=(a31*a30);
  a31=(a34+a31);
  a39=(a29*a39);
  a37=(a37*a30);
  a39=(a39+a37);
  a37=(a39*a40);
  a43=(a31+a37);
  if (res[0]!=0) res[0][13]=a43;
  a07=(a07+a36);
  if (res[0]!=0) res[0][14]=a07;
  a36=arg[1]? arg[1][10] : 0;
  a40=(a36-a40);
  a44=(a38*a40);
  a44=(a42+a44);
  a45=arg[0]? arg[0][7] : 0;
  a46=cos(a45);
  a47=(a38*a46);
  a48=sin(a45);
  a49=(a39*a48);
  a47=(a47-a49);
  a49=arg[1]? arg[1][23] : 0;
  a50=(a47*a49);
  a44=(a44+a50);
  if (res[0]!=0) res[0][15]=a44;
  a40=(a40*a39);
  a40=(a43+a40);
  a48=(a38*a48);
  a46=(a46*a39);
  a48=(a48+a46);
  a49=(a48*a49);
  a40=(a40+a49);
  if (res[0]!=0) res[0][16]=a40;
  a07=(a07+a45);
  if (res[0]!=0) res[0][17]=a07;
  a07=1.;
  if (res[1]!=0) res[1][0]=a07;
  a45=0.;
  if (res[1]!=0) res[1][1]=a45;
  if (res[1]!=0) res[1][2]=a45;
  if (res[1]!=0) res[1][3]=a07;
  if (res[1]!=0) res[1][4]=a45;
  if (res[1]!=0) res[1][5]=a45;
  if (res[1]!=0) res[1][6]=a07;
  if (res[1]!=0) res[1][7]=a45;
  if (res[1]!=0) res[1][8]=a45;
  if (res[1]!=0) res[1][9]=a07;
  if (res[1]!=0) res[1][10]=a45;
  if (res[1]!=0) res[1][11]=a45;
  if (res[1]!=0) res[1][12]=a07;
  if (res[1]!=0) res[1][13]=a45;
  if (res[1]!=0) res[1][14]=a45;
  if (res[1]!=0) res[1][15]=a07;
  if (res[1]!=0) res[1][16]=a45;
  if (res[1]!=0) res[1][17]=a45;
  if (res[1]!=0) res[1][18]=a45;
  if (res[1]!=0) res[1][19]=a07;
  if (res[1]!=0) res[1][20]=a45;
  if (res[1]!=0) res[1][21]=a45;
  if (res[1]!=0) res[1][22]=a07;
  if (res[1]!=0) res[1][23]=a45;
  if (res[1]!=0) res[1][24]=a45;
  if (res[1]!=0) res[1][25]=a07;
  if (res[1]!=0) res[1][26]=a45;
  if (res[1]!=0) res[1][27]=a45;
  if (res[1]!=0) res[1][28]=a07;
  if (res[1]!=0) res[1][29]=a45;
  if (res[1]!=0) res[1][30]=a45;
  if (res[1]!=0) res[1][31]=a07;
  if (res[1]!=0) res[1][32]=a45;
  if (res[1]!=0) res[1][33]=a45;
  if (res[1]!=0) res[1][34]=a07;
  if (res[1]!=0) res[1][35]=a45;
  if (res[1]!=0) res[1][36]=a45;
  if (res[1]!=0) res[1][37]=a45;
  if (res[1]!=0) res[1][38]=a07;
  a16=(a01-a16);
  if (res[1]!=0) res[1][39]=a16;
  a14=(a14-a00);
  if (res[1]!=0) res[1][40]=a14;
  if (res[1]!=0) res[1][41]=a07;
  a14=(a01-a25);
  if (res[1]!=0) res[1][42]=a14;
  a14=(a24-a00);
  if (res[1]!=0) res[1][43]=a14;
  if (res[1]!=0) res[1][44]=a07;
  a14=(a01-a34);
  if (res[1]!=0) res[1][45]=a14;
  a14=(a33-a00);
  if (res[1]!=0) res[1][46]=a14;
  if (res[1]!=0) res[1][47]=a07;
  a14=(a01-a43);
  if (res[1]!=0) res[1][48]=a14;
  a14=(a42-a00);
  if (res[1]!=0) res[1][49]=a14;
  if (res[1]!=0) res[1][50]=a07;
  a01=(a01-a40);
  if (res[1]!=0) res[1][51]=a01;
  a00=(a44-a00);
  if (res[1]!=0) res[1][52]=a00;
  if (res[1]!=0) res[1][53]=a07;
  if (res[1]!=0) res[1][54]=a45;
  if (res[1]!=0) res[1][55]=a45;
  if (res[1]!=0) res[1][56]=a45;
  a08=(-a08);
  if (res[1]!=0) res[1][57]=a08;
  if (res[1]!=0) res[1][58]=a13;
  if (res[1]!=0) res[1][59]=a07;
  a25=(a15-a25);
  if (res[1]!=0) res[1][60]=a25;
  a24=(a24-a06);
  if (res[1]!=0) res[1][61]=a24;
  if (res[1]!=0) res[1][62]=a07;
  a24=(a15-a34);
  if (res[1]!=0) res[1][63]=a24;
  a24=(a33-a06);
  if (res[1]!=0) res[1][64]=a24;
  if (res[1]!=0) res[1][65]=a07;
  a24=(a15-a43);
  if (res[1]!=0) res[1][66]=a24;
  a24=(a42-a06);
  if (res[1]!=0) res[1][67]=a24;
  if (res[1]!=0) res[1][68]=a07;
  a15=(a15-a40);
  if (res[1]!=0) res[1][69]=a15;
  a06=(a44-a06);
  if (res[1]!=0) res[1][70]=a06;
  if (res[1]!=0) res[1][71]=a07;
  if (res[1]!=0) res[1][72]=a45;
  if (res[1]!=0) res[1][73]=a45;
  if (res[1]!=0) res[1][74]=a45;
  if (res[1]!=0) res[1][75]=a45;
  if (res[1]!=0) res[1][76]=a45;
  if (res[1]!=0) res[1][77]=a45;
  a19=(-a19);
  if (res[1]!=0) res[1][78]=a19;
  if (res[1]!=0) res[1][79]=a23;
  if (res[1]!=0) res[1][80]=a07;
  a34=(a12-a34);
  if (res[1]!=0) res[1][81]=a34;
  a33=(a33-a17);
  if (res[1]!=0) res[1][82]=a33;
  if (res[1]!=0) res[1][83]=a07;
  a33=(a12-a43);
  if (res[1]!=0) res[1][84]=a33;
  a33=(a42-a17);
  if (res[1]!=0) res[1][85]=a33;
  if (res[1]!=0) res[1][86]=a07;
  a12=(a12-a40);
  if (res[1]!=0) res[1][87]=a12;
  a17=(a44-a17);
  if (res[1]!=0) res[1][88]=a17;
  if (res[1]!=0) res[1][89]=a07;
  if (res[1]!=0) res[1][90]=a45;
  if (res[1]!=0) res[1][91]=a45;
  if (res[1]!=0) res[1][92]=a45;
  if (res[1]!=0) res[1][93]=a45;
  if (res[1]!=0) res[1][94]=a45;
  if (res[1]!=0) res[1][95]=a45;
  if (res[1]!=0) res[1][96]=a45;
  if (res[1]!=0) res[1][97]=a45;
  if (res[1]!=0) res[1][98]=a45;
  a28=(-a28);
  if (res[1]!=0) res[1][99]=a28;
  if (res[1]!=0) res[1][100]=a32;
  if (res[1]!=0) res[1][101]=a07;
  a43=(a22-a43);
  if (res[1]!=0) res[1][102]=a43;
  a42=(a42-a26);
  if (res[1]!=0) res[1][103]=a42;
  if (res[1]!=0) res[1][104]=a07;
  a22=(a22-a40);
  if (res[1]!=0) res[1][105]=a22;
  a26=(a44-a26);
  if (res[1]!=0) res[1][106]=a26;
  if (res[1]!=0) res[1][107]=a07;
  if (res[1]!=0) res[1][108]=a45;
  if (res[1]!=0) res[1][109]=a45;
  if (res[1]!=0) res[1][110]=a45;
  if (res[1]!=0) res[1][111]=a45;
  if (res[1]!=0) res[1][112]=a45;
  if (res[1]!=0) res[1][113]=a45;
  if (res[1]!=0) res[1][114]=a45;
  if (res[1]!=0) res[1][115]=a45;
  if (res[1]!=0) res[1][116]=a45;
  if (res[1]!=0) res[1][117]=a45;
  if (res[1]!=0) res[1][118]=a45;
  if (res[1]!=0) res[1][119]=a45;
  a37=(-a37);
  if (res[1]!=0) res[1][120]=a37;
  if (res[1]!=0) res[1][121]=a41;
  if (res[1]!=0) res[1][122]=a07;
  a31=(a31-a40);
  if (res[1]!=0) res[1][123]=a31;
  a44=(a44-a35);
  if (res[1]!=0) res[1][124]=a44;
  if (res[1]!=0) res[1][125]=a07;
  if (res[1]!=0) res[1][126]=a45;
  if (res[1]!=0) res[1][127]=a45;
  if (res[1]!=0) res[1][128]=a45;
  if (res[1]!=0) res[1][129]=a45;
  if (res[1]!=0) res[1][130]=a45;
  if (res[1]!=0) res[1][131]=a45;
  if (res[1]!=0) res[1][132]=a45;
  if (res[1]!=0) res[1][133]=a45;
  if (res[1]!=0) res[1][134]=a45;
  if (res[1]!=0) res[1][135]=a45;
  if (res[1]!=0) res[1][136]=a45;
  if (res[1]!=0) res[1][137]=a45;
  if (res[1]!=0) res[1][138]=a45;
  if (res[1]!=0) res[1][139]=a45;
  if (res[1]!=0) res[1][140]=a45;
  a49=(-a49);
  if (res[1]!=0) res[1][141]=a49;
  if (res[1]!=0) res[1][142]=a50;
  if (res[1]!=0) res[1][143]=a07;
  a07=arg[1]? arg[1][24] : 0;
  if (res[2]!=0) res[2][0]=a07;
  if (res[2]!=0) res[2][1]=a45;
  a50=arg[1]? arg[1][30] : 0;
  a49=(a50*a48);
  a44=arg[1]? arg[1][29] : 0;
  a35=(a44*a39);
  a35=(a49+a35);
  a31=arg[1]? arg[1][28] : 0;
  a40=(a31*a30);
  a40=(a35+a40);
  a41=arg[1]? arg[1][27] : 0;
  a37=(a41*a21);
  a37=(a40+a37);
  a26=arg[1]? arg[1][26] : 0;
  a22=(a26*a11);
  a22=(a37+a22);
  a42=arg[1]? arg[1][25] : 0;
  a43=(a42*a10);
  a43=(a22+a43);
  a43=(-a43);
  if (res[2]!=0) res[2][2]=a43;
  a32=(-a22);
  if (res[2]!=0) res[2][3]=a32;
  a28=(-a37);
  if (res[2]!=0) res[2][4]=a28;
  a17=(-a40);
  if (res[2]!=0) res[2][5]=a17;
  a12=(-a35);
  if (res[2]!=0) res[2][6]=a12;
  a33=(-a49);
  if (res[2]!=0) res[2][7]=a33;
  if (res[2]!=0) res[2][8]=a45;
  if (res[2]!=0) res[2][9]=a07;
  a50=(a50*a47);
  a44=(a44*a38);
  a44=(a50+a44);
  a31=(a31*a29);
  a31=(a44+a31);
  a41=(a41*a20);
  a41=(a31+a41);
  a26=(a26*a09);
  a26=(a41+a26);
  a42=(a42*a03);
  a42=(a26+a42);
  if (res[2]!=0) res[2][10]=a42;
  if (res[2]!=0) res[2][11]=a26;
  if (res[2]!=0) res[2][12]=a41;
  if (res[2]!=0) res[2][13]=a31;
  if (res[2]!=0) res[2][14]=a44;
  if (res[2]!=0) res[2][15]=a50;
  if (res[2]!=0) res[2][16]=a43;
  if (res[2]!=0) res[2][17]=a42;
  a42=(a38*a36);
  a42=(a50*a42);
  a36=(a39*a36);
  a36=(a49*a36);
  a42=(a42+a36);
  a36=arg[1]? arg[1][57] : 0;
  a43=(a42+a36);
  a42=(a43+a42);
  a07=arg[1]? arg[1][56] : 0;
  a42=(a42+a07);
  a07=(a29*a27);
  a45=(a44*a07);
  a27=(a30*a27);
  a34=(a35*a27);
  a45=(a45+a34);
  a34=(a42+a45);
  a45=(a34+a45);
  a23=arg[1]? arg[1][55] : 0;
  a45=(a45+a23);
  a23=(a20*a18);
  a19=(a31*a23);
  a18=(a21*a18);
  a06=(a40*a18);
  a19=(a19+a06);
  a06=(a45+a19);
  a19=(a06+a19);
  a15=arg[1]? arg[1][54] : 0;
  a19=(a19+a15);
  a15=(a09*a02);
  a24=(a41*a15);
  a02=(a11*a02);
  a25=(a37*a02);
  a24=(a24+a25);
  a25=(a19+a24);
  a24=(a25+a24);
  a13=arg[1]? arg[1][53] : 0;
  a24=(a24+a13);
  a13=(a26*a05);
  a22=(a22*a04);
  a13=(a13+a22);
  a22=(a24+a13);
  a13=(a22+a13);
  a08=arg[1]? arg[1][52] : 0;
  a13=(a13+a08);
  if (res[2]!=0) res[2][18]=a13;
  if (res[2]!=0) res[2][19]=a22;
  a13=(a41*a05);
  a37=(a37*a04);
  a13=(a13+a37);
  a13=(a25+a13);
  if (res[2]!=0) res[2][20]=a13;
  a37=(a31*a15);
  a08=(a40*a02);
  a37=(a37+a08);
  a37=(a06+a37);
  a08=(a31*a05);
  a40=(a40*a04);
  a08=(a08+a40);
  a08=(a37+a08);
  if (res[2]!=0) res[2][21]=a08;
  a40=(a44*a23);
  a00=(a35*a18);
  a40=(a40+a00);
  a40=(a34+a40);
  a00=(a44*a15);
  a01=(a35*a02);
  a00=(a00+a01);
  a00=(a40+a00);
  a01=(a44*a05);
  a35=(a35*a04);
  a01=(a01+a35);
  a01=(a00+a01);
  if (res[2]!=0) res[2][22]=a01;
  a07=(a50*a07);
  a27=(a49*a27);
  a07=(a07+a27);
  a07=(a43+a07);
  a23=(a50*a23);
  a18=(a49*a18);
  a23=(a23+a18);
  a23=(a07+a23);
  a15=(a50*a15);
  a02=(a49*a02);
  a15=(a15+a02);
  a15=(a23+a15);
  a05=(a50*a05);
  a49=(a49*a04);
  a05=(a05+a49);
  a05=(a15+a05);
  if (res[2]!=0) res[2][23]=a05;
  if (res[2]!=0) res[2][24]=a32;
  if (res[2]!=0) res[2][25]=a26;
  if (res[2]!=0) res[2][26]=a22;
  if (res[2]!=0) res[2][27]=a24;
  if (res[2]!=0) res[2][28]=a25;
  if (res[2]!=0) res[2][29]=a37;
  if (res[2]!=0) res[2][30]=a00;
  if (res[2]!=0) res[2][31]=a15;
  if (res[2]!=0) res[2][32]=a28;
  if (res[2]!=0) res[2][33]=a41;
  if (res[2]!=0) res[2][34]=a13;
  if (res[2]!=0) res[2][35]=a25;
  if (res[2]!=0) res[2][36]=a19;
  if (res[2]!=0) res[2][37]=a06;
  if (res[2]!=0) res[2][38]=a40;
  if (res[2]!=0) res[2][39]=a23;
  if (res[2]!=0) res[2][40]=a17;
  if (res[2]!=0) res[2][41]=a31;
  if (res[2]!=0) res[2][42]=a08;
  if (res[2]!=0) res[2][43]=a37;
  if (res[2]!=0) res[2][44]=a06;
  if (res[2]!=0) res[2][45]=a45;
  if (res[2]!=0) res[2][46]=a34;
  if (res[2]!=0) res[2][47]=a07;
  if (res[2]!=0) res[2][48]=a12;
  if (res[2]!=0) res[2][49]=a44;
  if (res[2]!=0) res[2][50]=a01;
  if (res[2]!=0) res[2][51]=a00;
  if (res[2]!=0) res[2][52]=a40;
  if (res[2]!=0) res[2][53]=a34;
  if (res[2]!=0) res[2][54]=a42;
  if (res[2]!=0) res[2][55]=a43;
  if (res[2]!=0) res[2][56]=a33;
  if (res[2]!=0) res[2][57]=a50;
  if (res[2]!=0) res[2][58]=a05;
  if (res[2]!=0) res[2][59]=a15;
  if (res[2]!=0) res[2][60]=a23;
  if (res[2]!=0) res[2][61]=a07;
  if (res[2]!=0) res[2][62]=a43;
  if (res[2]!=0) res[2][63]=a36;
  if (res[3]!=0) res[3][0]=a03;
  if (res[3]!=0) res[3][1]=a10;
  if (res[3]!=0) res[3][2]=a09;
  if (res[3]!=0) res[3][3]=a11;
  if (res[3]!=0) res[3][4]=a20;
  if (res[3]!=0) res[3][5]=a21;
  if (res[3]!=0) res[3][6]=a29;
  if (res[3]!=0) res[3][7]=a30;
  if (res[3]!=0) res[3][8]=a38;
  if (res[3]!=0) res[3][9]=a39;
  if (res[3]!=0) res[3][10]=a47;
  if (res[3]!=0) res[3][11]=a48;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na5_scene_kinematics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_scene_kinematics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_scene_kinematics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_scene_kinematics_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_scene_kinematics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na5_scene_kinematics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_scene_kinematics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_scene_kinematics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    case 1: return "J";
    case 2: return "M";
    case 3: return "cs";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_scene_kinematics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_scene_kinematics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_scene_kinematics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na5_batch_scene_kinematics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 52);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 18;
    r[1] = res[1] + i * 144;
    r[2] = res[2] + i * 64;
    r[3] = res[3] + i * 12;
    if (snakecg_na5_scene_kinematics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
