/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for scene_kinematics() of
 * generated/na6/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 522fe595aab63e52670af90656908e991192d778246ab53ba223a16866b70733
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na6_scene_kinematics_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na6_scene_kinematics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {3, 7, 1};
static const casadi_int casadi_s3[3] = {21, 9, 1};
static const casadi_int casadi_s4[3] = {9, 9, 1};
static const casadi_int casadi_s5[3] = {2, 7, 1};

/* snakecg_na6_scene_kinematics:(q[9],K[71])->(poses[3x7],J[21x9],M[9x9],cs[2x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][7] : 0;
  a05=arg[1]? arg[1][21] : 0;
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
  a12=arg[1]? arg[1][22] : 0;
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
  a02=arg[1]? arg[1][8] : 0;
  a12=(a02-a12);
  a17=(a09*a12);
  a17=(a14+a17);
  a18=arg[0]? arg[0][4] : 0;
  a19=cos(a18);
  a20=(a09*a19);
  a21=sin(a18);
  a22=(a11*a21);
  a20=(a20-a22);
  a22=arg[1]? arg[1][23] : 0;
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
  a18=arg[1]? arg[1][9] : 0;
  a22=(a18-a22);
  a26=(a20*a22);
  a26=(a24+a26);
  a27=arg[0]? arg[0][5] : 0;
  a28=cos(a27);
  a29=(a20*a28);
  a30=sin(a27);
  a31=(a21*a30);
  a29=(a29-a31);
  a31=arg[1]? arg[1][24] : 0;
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
  a27=arg[1]? arg[1][10] : 0;
  a31=(a27-a31);
  a35=(a29*a31);
  a35=(a33+a35);
  a36=arg[0]? arg[0][6] : 0;
  a37=cos(a36);
  a38=(a29*a37);
  a39=sin(a36);
  a40=(a30*a39);
  a38=(a38-a40);
  a40=arg[1]? arg[1][25] : 0;
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
  a36=arg[1]? arg[1][11] : 0;
  a40=(a36-a40);
  a44=(a38*a40);
  a44=(a42+a44);
  a45=arg[0]? arg[0][7] : 0;
  a46=cos(a45);
  a47=(a38*a46);
  a48=sin(a45);
  a49=(a39*a48);
  a47=(a47-a49);
  a49=arg[1]? arg[1][26] : 0;
  a50=(a47*a49);
  a51=(a44+a50);
  if (res[0]!=0) res[0][15]=a51;
  a40=(a40*a39);
  a40=(a43+a40);
  a48=(a38*a48);
  a46=(a46*a39);
  a48=(a48+a46);
  a46=(a48*a49);
  a52=(a40+a46);
  if (res[0]!=0) res[0][16]=a52;
  a07=(a07+a45);
  if (res[0]!=0) res[0][17]=a07;
  a45=arg[1]? arg[1][12] : 0;
  a49=(a45-a49);
  a53=(a47*a49);
  a53=(a51+a53);
  a54=arg[0]? arg[0][8] : 0;
  a55=cos(a54);
  a56=(a47*a55);
  a57=sin(a54);
  a58=(a48*a57);
  a56=(a56-a58);
  a58=arg[1]? arg[1][27] : 0;
  a59=(a56*a58);
  a53=(a53+a59);
  if (res[0]!=0) res[0][18]=a53;
  a49=(a49*a48);
  a49=(a52+a49);
  a57=(a47*a57);
  a55=(a55*a48);
  a57=(a57+a55);
  a58=(a57*a58);
  a49=(a49+a58);
  if (res[0]!=0) res[0][19]=a49;
  a07=(a07+a54);
  if (res[0]!=0) res[0][20]=a07;
  a07=1.;
  if (res[1]!=0) res[1][0]=a07;
  a54=0.;
  if (res[1]!=0) res[1][1]=a54;
  if (res[1]!=0) res[1][2]=a54;
  if (res[1]!=0) res[1][3]=a07;
  if (res[1]!=0) res[1][4]=a54;
  if (res[1]!=0) res[1][5]=a54;
  if (res[1]!=0) res[1][6]=a07;
  if (res[1]!=0) res[1][7]=a54;
  if (res[1]!=0) res[1][8]=a54;
  if (res[1]!=0) res[1][9]=a07;
  if (res[1]!=0) res[1][10]=a54;
  if (res[1]!=0) res[1][11]=a54;
  if (res[1]!=0) res[1][12]=a07;
  if (res[1]!=0) res[1][13]=a54;
  if (res[1]!=0) res[1][14]=a54;
  if (res[1]!=0) res[1][15]=a07;
  if (res[1]!=0) res[1][16]=a54;
  if (res[1]!=0) res[1][17]=a54;
  if (res[1]!=0) res[1][18]=a07;
  if (res[1]!=0) res[1][19]=a54;
  if (res[1]!=0) res[1][20]=a54;
  if (res[1]!=0) res[1][21]=a54;
  if (res[1]!=0) res[1][22]=a07;
  if (res[1]!=0) res[1][23]=a54;
  if (res[1]!=0) res[1][24]=a54;
  if (res[1]!=0) res[1][25]=a07;
  if (res[1]!=0) res[1][26]=a54;
  if (res[1]!=0) res[1][27]=a54;
  if (res[1]!=0) res[1][28]=a07;
  if (res[1]!=0) res[1][29]=a54;
  if (res[1]!=0) res[1][30]=a54;
  if (res[1]!=0) res[1][31]=a07;
  if (res[1]!=0) res[1][32]=a54;
  if (res[1]!=0) res[1][33]=a54;
  if (res[1]!=0) res[1][34]=a07;
  if (res[1]!=0) res[1][35]=a54;
  if (res[1]!=0) res[1][36]=a54;
  if (res[1]!=0) res[1][37]=a07;
  if (res[1]!=0) res[1][38]=a54;
  if (res[1]!=0) res[1][39]=a54;
  if (res[1]!=0) res[1][40]=a07;
  if (res[1]!=0) res[1][41]=a54;
  if (res[1]!=0) res[1][42]=a54;
  if (res[1]!=0) res[1][43]=a54;
  if (res[1]!=0) res[1][44]=a07;
  a16=(a01-a16);
  if (res[1]!=0) res[1][45]=a16;
  a14=(a14-a00);
  if (res[1]!=0) res[1][46]=a14;
  if (res[1]!=0) res[1][47]=a07;
  a14=(a01-a25);
  if (res[1]!=0) res[1][48]=a14;
  a14=(a24-a00);
  if (res[1]!=0) res[1][49]=a14;
  if (res[1]!=0) res[1][50]=a07;
  a14=(a01-a34);
  if (res[1]!=0) res[1][51]=a14;
  a14=(a33-a00);
  if (res[1]!=0) res[1][52]=a14;
  if (res[1]!=0) res[1][53]=a07;
  a14=(a01-a43);
  if (res[1]!=0) res[1][54]=a14;
  a14=(a42-a00);
  if (res[1]!=0) res[1][55]=a14;
  if (res[1]!=0) res[1][56]=a07;
  a14=(a01-a52);
  if (res[1]!=0) res[1][57]=a14;
  a14=(a51-a00);
  if (res[1]!=0) res[1][58]=a14;
  if (res[1]!=0) res[1][59]=a07;
  a01=(a01-a49);
  if (res[1]!=0) res[1][60]=a01;
  a00=(a53-a00);
  if (res[1]!=0) res[1][61]=a00;
  if (res[1]!=0) res[1][62]=a07;
  if (res[1]!=0) res[1][63]=a54;
  if (res[1]!=0) res[1][64]=a54;
  if (res[1]!=0) res[1][65]=a54;
  a08=(-a08);
  if (res[1]!=0) res[1][66]=a08;
  if (res[1]!=0) res[1][67]=a13;
  if (res[1]!=0) res[1][68]=a07;
  a25=(a15-a25);
  if (res[1]!=0) res[1][69]=a25;
  a24=(a24-a06);
  if (res[1]!=0) res[1][70]=a24;
  if (res[1]!=0) res[1][71]=a07;
  a24=(a15-a34);
  if (res[1]!=0) res[1][72]=a24;
  a24=(a33-a06);
  if (res[1]!=0) res[1][73]=a24;
  if (res[1]!=0) res[1][74]=a07;
  a24=(a15-a43);
  if (res[1]!=0) res[1][75]=a24;
  a24=(a42-a06);
  if (res[1]!=0) res[1][76]=a24;
  if (res[1]!=0) res[1][77]=a07;
  a24=(a15-a52);
  if (res[1]!=0) res[1][78]=a24;
  a24=(a51-a06);
  if (res[1]!=0) res[1][79]=a24;
  if (res[1]!=0) res[1][80]=a07;
  a15=(a15-a49);
  if (res[1]!=0) res[1][81]=a15;
  a06=(a53-a06);
  if (res[1]!=0) res[1][82]=a06;
  if (res[1]!=0) res[1][83]=a07;
  if (res[1]!=0) res[1][84]=a54;
  if (res[1]!=0) res[1][85]=a54;
  if (res[1]!=0) res[1][86]=a54;
  if (res[1]!=0) res[1][87]=a54;
  if (res[1]!=0) res[1][88]=a54;
  if (res[1]!=0) res[1][89]=a54;
  a19=(-a19);
  if (res[1]!=0) res[1][90]=a19;
  if (res[1]!=0) res[1][91]=a23;
  if (res[1]!=0) res[1][92]=a07;
  a34=(a12-a34);
  if (res[1]!=0) res[1][93]=a34;
  a33=(a33-a17);
  if (res[1]!=0) res[1][94]=a33;
  if (res[1]!=0) res[1][95]=a07;
  a33=(a12-a43);
  if (res[1]!=0) res[1][96]=a33;
  a33=(a42-a17);
  if (res[1]!=0) res[1][97]=a33;
  if (res[1]!=0) res[1][98]=a07;
  a33=(a12-a52);
  if (res[1]!=0) res[1][99]=a33;
  a33=(a51-a17);
  if (res[1]!=0) res[1][100]=a33;
  if (res[1]!=0) res[1][101]=a07;
  a12=(a12-a49);
  if (res[1]!=0) res[1][102]=a12;
  a17=(a53-a17);
  if (res[1]!=0) res[1][103]=a17;
  if (res[1]!=0) res[1][104]=a07;
  if (res[1]!=0) res[1][105]=a54;
  if (res[1]!=0) res[1][106]=a54;
  if (res[1]!=0) res[1][107]=a54;
  if (res[1]!=0) res[1][108]=a54;
  if (res[1]!=0) res[1][109]=a54;
  if (res[1]!=0) res[1][110]=a54;
  if (res[1]!=0) res[1][111]=a54;
  if (res[1]!=0) res[1][112]=a54;
  if (res[1]!=0) res[1][113]=a54;
  a28=(-a28);
  if (res[1]!=0) res[1][114]=a28;
  if (res[1]!=0) res[1][115]=a32;
  if (res[1]!=0) res[1][116]=a07;
  a43=(a22-a43);
  if (res[1]!=0) res[1][117]=a43;
  a42=(a42-a26);
  if (res[1]!=0) res[1][118]=a42;
  if (res[1]!=0) res[1][119]=a07;
  a42=(a22-a52);
  if (res[1]!=0) res[1][120]=a42;
  a42=(a51-a26);
  if (res[1]!=0) res[1][121]=a42;
  if (res[1]!=0) res[1][122]=a07;
  a22=(a22-a49);
  if (res[1]!=0) res[1][123]=a22;
  a26=(a53-a26);
  if (res[1]!=0) res[1][124]=a26;
  if (res[1]!=0) res[1][125]=a07;
  if (res[1]!=0) res[1][126]=a54;
  if (res[1]!=0) res[1][127]=a54;
  if (res[1]!=0) res[1][128]=a54;
  if (res[1]!=0) res[1][129]=a54;
  if (res[1]!=0) res[1][130]=a54;
  if (res[1]!=0) res[1][131]=a54;
  if (res[1]!=0) res[1][132]=a54;
  if (res[1]!=0) res[1][133]=a54;
  if (res[1]!=0) res[1][134]=a54;
  if (res[1]!=0) res[1][135]=a54;
  if (res[1]!=0) res[1][136]=a54;
  if (res[1]!=0) res[1][137]=a54;
  a37=(-a37);
  if (res[1]!=0) res[1][138]=a37;
  if (res[1]!=0) res[1][139]=a41;
  if (res[1]!=0) res[1][140]=a07;
  a52=(a31-a52);
  if (res[1]!=0) res[1][141]=a52;
  a51=(a51-a35);
  if (res[1]!=0) res[1][142]=a51;
  if (res[1]!=0) res[1][143]=a07;
  a31=(a31-a49);
  if (res[1]!=0) res[1][144]=a31;
  a35=(a53-a35);
  if (res[1]!=0) res[1][145]=a35;
  if (res[1]!=0) res[1][146]=a07;
  if (res[1]!=0) res[1][147]=a54;
  if (res[1]!=0) res[1][148]=a54;
  if (res[1]!=0) res[1][149]=a54;
  if (res[1]!=0) res[1][150]=a54;
  if (res[1]!=0) res[1][151]=a54;
  if (res[1]!=0) res[1][152]=a54;
  if (res[1]!=0) res[1][153]=a54;
  if (res[1]!=0) res[1][154]=a54;
  if (res[1]!=0) res[1][155]=a54;
  if (res[1]!=0) res[1][156]=a54;
  if (res[1]!=0) res[1][157]=a54;
  if (res[1]!=0) res[1][158]=a54;
  if (res[1]!=0) res[1][159]=a54;
  if (res[1]!=0) res[1][160]=a54;
  if (res[1]!=0) res[1][161]=a54;
  a46=(-a46);
  if (res[1]!=0) res[1][162]=a46;
  if (res[1]!=0) res[1][163]=a50;
  if (res[1]!=0) res[1][164]=a07;
  a40=(a40-a49);
  if (res[1]!=0) res[1][165]=a40;
  a53=(a53-a44);
  if (res[1]!=0) res[1][166]=a53;
  if (res[1]!=0) res[1][167]=a07;
  if (res[1]!=0) res[1][168]=a54;
  if (res[1]!=0) res[1][169]=a54;
  if (res[1]!=0) res[1][170]=a54;
  if (res[1]!=0) res[1][171]=a54;
  if (res[1]!=0) res[1][172]=a54;
  if (res[1]!=0) res[1][173]=a54;
  if (res[1]!=0) res[1][174]=a54;
  if (res[1]!=0) res[1][175]=a54;
  if (res[1]!=0) res[1][176]=a54;
  if (res[1]!=0) res[1][177]=a54;
  if (res[1]!=0) res[1][178]=a54;
  if (res[1]!=0) res[1][179]=a54;
  if (res[1]!=0) res[1][180]=a54;
  if (res[1]!=0) res[1][181]=a54;
  if (res[1]!=0) res[1][182]=a54;
  if (res[1]!=0) res[1][183]=a54;
  if (res[1]!=0) res[1][184]=a54;
  if (res[1]!=0) res[1][185]=a54;
  a58=(-a58);
  if (res[1]!=0) res[1][186]=a58;
  if (res[1]!=0) res[1][187]=a59;
  if (res[1]!=0) res[1][188]=a07;
  a07=arg[1]? arg[1][28] : 0;
  if (res[2]!=0) res[2][0]=a07;
  if (res[2]!=0) res[2][1]=a54;
  a59=arg[1]? arg[1][35] : 0;
  a58=(a59*a57);
  a53=arg[1]? arg[1][34] : 0;
  a44=(a53*a48);
  a44=(a58+a44);
  a40=arg[1]? arg[1][33] : 0;
  a49=(a40*a39);
  a49=(a44+a49);
  a50=arg[1]? arg[1][32] : 0;
  a46=(a50*a30);
  a46=(a49+a46);
  a35=arg[1]? arg[1][31] : 0;
  a31=(a35*a21);
  a31=(a46+a31);
  a51=arg[1]? arg[1][30] : 0;
  a52=(a51*a11);
  a52=(a31+a52);
  a41=arg[1]? arg[1][29] : 0;
  a37=(a41*a10);
  a37=(a52+a37);
  a37=(-a37);
  if (res[2]!=0) res[2][2]=a37;
  a26=(-a52);
  if (res[2]!=0) res[2][3]=a26;
  a22=(-a31);
  if (res[2]!=0) res[2][4]=a22;
  a42=(-a46);
  if (res[2]!=0) res[2][5]=a42;
  a43=(-a49);
  if (res[2]!=0) res[2][6]=a43;
  a32=(-a44);
  if (res[2]!=0) res[2][7]=a32;
  a28=(-a58);
  if (res[2]!=0) res[2][8]=a28;
  if (res[2]!=0) res[2][9]=a54;
  if (res[2]!=0) res[2][10]=a07;
  a59=(a59*a56);
  a53=(a53*a47);
  a53=(a59+a53);
  a40=(a40*a38);
  a40=(a53+a40);
  a50=(a50*a29);
  a50=(a40+a50);
  a35=(a35*a20);
  a35=(a50+a35);
  a51=(a51*a09);
  a51=(a35+a51);
  a41=(a41*a03);
  a41=(a51+a41);
  if (res[2]!=0) res[2][11]=a41;
  if (res[2]!=0) res[2][12]=a51;
  if (res[2]!=0) res[2][13]=a35;
  if (res[2]!=0) res[2][14]=a50;
  if (res[2]!=0) res[2][15]=a40;
  if (res[2]!=0) res[2][16]=a53;
  if (res[2]!=0) res[2][17]=a59;
  if (res[2]!=0) res[2][18]=a37;
  if (res[2]!=0) res[2][19]=a41;
  a41=(a47*a45);
  a41=(a59*a41);
  a45=(a48*a45);
  a45=(a58*a45);
  a41=(a41+a45);
  a45=arg[1]? arg[1][70] : 0;
  a37=(a41+a45);
  a41=(a37+a41);
  a07=arg[1]? arg[1][69] : 0;
  a41=(a41+a07);
  a07=(a38*a36);
  a54=(a53*a07);
  a36=(a39*a36);
  a17=(a44*a36);
  a54=(a54+a17);
  a17=(a41+a54);
  a54=(a17+a54);
  a12=arg[1]? arg[1][68] : 0;
  a54=(a54+a12);
  a12=(a29*a27);
  a33=(a40*a12);
  a27=(a30*a27);
  a34=(a49*a27);
  a33=(a33+a34);
  a34=(a54+a33);
  a33=(a34+a33);
  a23=arg[1]? arg[1][67] : 0;
  a33=(a33+a23);
  a23=(a20*a18);
  a19=(a50*a23);
  a18=(a21*a18);
  a06=(a46*a18);
  a19=(a19+a06);
  a06=(a33+a19);
  a19=(a06+a19);
  a15=arg[1]? arg[1][66] : 0;
  a19=(a19+a15);
  a15=(a09*a02);
  a24=(a35*a15);
  a02=(a11*a02);
  a25=(a31*a02);
  a24=(a24+a25);
  a25=(a19+a24);
  a24=(a25+a24);
  a13=arg[1]? arg[1][65] : 0;
  a24=(a24+a13);
  a13=(a51*a05);
  a52=(a52*a04);
  a13=(a13+a52);
  a52=(a24+a13);
  a13=(a52+a13);
  a08=arg[1]? arg[1][64] : 0;
  a13=(a13+a08);
  if (res[2]!=0) res[2][20]=a13;
  if (res[2]!=0) res[2][21]=a52;
  a13=(a35*a05);
  a31=(a31*a04);
  a13=(a13+a31);
  a13=(a25+a13);
  if (res[2]!=0) res[2][22]=a13;
  a31=(a50*a15);
  a08=(a46*a02);
  a31=(a31+a08);
  a31=(a06+a31);
  a08=(a50*a05);
  a46=(a46*a04);
  a08=(a08+a46);
  a08=(a31+a08);
  if (res[2]!=0) res[2][23]=a08;
  a46=(a40*a23);
  a00=(a49*a18);
  a46=(a46+a00);
  a46=(a34+a46);
  a00=(a40*a15);
  a01=(a49*a02);
  a00=(a00+a01);
  a00=(a46+a00);
  a01=(a40*a05);
  a49=(a49*a04);
  a01=(a01+a49);
  a01=(a00+a01);
  if (res[2]!=0) res[2][24]=a01;
  a49=(a53*a12);
  a14=(a44*a27);
  a49=(a49+a14);
  a49=(a17+a49);
  a14=(a53*a23);
  a16=(a44*a18);
  a14=(a14+a16);
  a14=(a49+a14);
  a16=(a53*a15);
  a55=(a44*a02);
  a16=(a16+a55);
  a16=(a14+a16);
  a55=(a53*a05);
  a44=(a44*a04);
  a55=(a55+a44);
  a55=(a16+a55);
  if (res[2]!=0) res[2][25]=a55;
  a07=(a59*a07);
  a36=(a58*a36);
  a07=(a07+a36);
  a07=(a37+a07);
  a12=(a59*a12);
  a27=(a58*a27);
  a12=(a12+a27);
  a12=(a07+a12);
  a23=(a59*a23);
  a18=(a58*a18);
  a23=(a23+a18);
  a23=(a12+a23);
  a15=(a59*a15);
  a02=(a58*a02);
  a15=(a15+a02);
  a15=(a23+a15);
  a05=(a59*a05);
  a58=(a58*a04);
  a05=(a05+a58);
  a05=(a15+a05);
  if (res[2]!=0) res[2][26]=a05;
  if (res[2]!=0) res[2][27]=a26;
  if (res[2]!=0) res[2][28]=a51;
  if (res[2]!=0) res[2][29]=a52;
  if (res[2]!=0) res[2][30]=a24;
  if (res[2]!=0) res[2][31]=a25;
  if (res[2]!=0) res[2][32]=a31;
  if (res[2]!=0) res[2][33]=a00;
  if (res[2]!=0) res[2][34]=a16;
  if (res[2]!=0) res[2][35]=a15;
  if (res[2]!=0) res[2][36]=a22;
  if (res[2]!=0) res[2][37]=a35;
  if (res[2]!=0) res[2][38]=a13;
  if (res[2]!=0) res[2][39]=a25;
  if (res[2]!=0) res[2][40]=a19;
  if (res[2]!=0) res[2][41]=a06;
  if (res[2]!=0) res[2][42]=a46;
  if (res[2]!=0) res[2][43]=a14;
  if (res[2]!=0) res[2][44]=a23;
  if (res[2]!=0) res[2][45]=a42;
  if (res[2]!=0) res[2][46]=a50;
  if (res[2]!=0) res[2][47]=a08;
  if (res[2]!=0) res[2][48]=a31;
  if (res[2]!=0) res[2][49]=a06;
  if (res[2]!=0) res[2][50]=a33;
  if (res[2]!=0) res[2][51]=a34;
  if (res[2]!=0) res[2][52]=a49;
  if (res[2]!=0) res[2][53]=a12;
  if (res[2]!=0) res[2][54]=a43;
  if (res[2]!=0) res[2][55]=a40;
  if (res[2]!=0) res[2][56]=a01;
  if (res[2]!=0) res[2][57]=a00;
  if (res[2]!=0) res[2][58]=a46;
  if (res[2]!=0) res[2][59]=a34;
  if (res[2]!=0) res[2][60]=a54;
  if (res[2]!=0) res[2][61]=a17;
  if (res[2]!=0) res[2][62]=a07;
  if (res[2]!=0) res[2][63]=a32;
  if (res[2]!=0) res[2][64]=a53;
  if (res[2]!=0) res[2][65]=a55;
  if (res[2]!=0) res[2][66]=a16;
  if (res[2]!=0) res[2][67]=a14;
  if (res[2]!=0) res[2][68]=a49;
  if (res[2]!=0) res[2][69]=a17;
  if (res[2]!=0) res[2][70]=a41;
  if (res[2]!=0) res[2][71]=a37;
  if (res[2]!=0) res[2][72]=a28;
  if (res[2]!=0) res[2][73]=a59;
  if (res[2]!=0) res[2][74]=a05;
  if (res[2]!=0) res[2][75]=a15;
  if (res[2]!=0) res[2][76]=a23;
  if (res[2]!=0) res[2][77]=a12;
  if (res[2]!=0) res[2][78]=a07;
  if (res[2]!=0) res[2][79]=a37;
  if (res[2]!=0) res[2][80]=a45;
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
  if (res[3]!=0) res[3][12]=a56;
  if (res[3]!=0) res[3][13]=a57;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na6_scene_kinematics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_scene_kinematics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_scene_kinematics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_scene_kinematics_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_scene_kinematics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na6_scene_kinematics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_scene_kinematics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_scene_kinematics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    case 1: return "J";
    case 2: return "M";
    case 3: return "cs";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_scene_kinematics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_scene_kinematics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_scene_kinematics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na6_batch_scene_kinematics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 61);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 21;
    r[1] = res[1] + i * 189;
    r[2] = res[2] + i * 81;
    r[3] = res[3] + i * 14;
    if (snakecg_na6_scene_kinematics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
