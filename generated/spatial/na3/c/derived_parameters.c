/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
 * generated/spatial/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: bf1c4fd4f801e736fb72ccb4a73063ec2be6511d38a40d0e800777ceac032ebe
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp3_derived_parameters_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_derived_parameters_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {12, 1, 1};
static const casadi_int casadi_s2[3] = {24, 1, 1};
static const casadi_int casadi_s3[3] = {9, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};
static const casadi_int casadi_s5[3] = {169, 1, 1};

/* snakecg_sp3_derived_parameters:(link_mass[4],link_com[12],link_inertia[24],joint_xyz[9],joint_rpy[9],joint_axis[9],gravity[3])->(K[169]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87, a88;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a00;
  a00=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a00;
  a00=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][4]=a00;
  a01=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][5]=a01;
  a02=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][6]=a02;
  a03=arg[1]? arg[1][3] : 0;
  if (res[0]!=0) res[0][7]=a03;
  a04=arg[1]? arg[1][4] : 0;
  if (res[0]!=0) res[0][8]=a04;
  a05=arg[1]? arg[1][5] : 0;
  if (res[0]!=0) res[0][9]=a05;
  a06=arg[1]? arg[1][6] : 0;
  if (res[0]!=0) res[0][10]=a06;
  a07=arg[1]? arg[1][7] : 0;
  if (res[0]!=0) res[0][11]=a07;
  a08=arg[1]? arg[1][8] : 0;
  if (res[0]!=0) res[0][12]=a08;
  a09=arg[1]? arg[1][9] : 0;
  if (res[0]!=0) res[0][13]=a09;
  a10=arg[1]? arg[1][10] : 0;
  if (res[0]!=0) res[0][14]=a10;
  a11=arg[1]? arg[1][11] : 0;
  if (res[0]!=0) res[0][15]=a11;
  a12=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][16]=a12;
  a13=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][17]=a13;
  a14=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][18]=a14;
  a15=arg[2]? arg[2][3] : 0;
  if (res[0]!=0) res[0][19]=a15;
  a16=arg[2]? arg[2][4] : 0;
  if (res[0]!=0) res[0][20]=a16;
  a17=arg[2]? arg[2][5] : 0;
  if (res[0]!=0) res[0][21]=a17;
  a18=arg[2]? arg[2][6] : 0;
  if (res[0]!=0) res[0][22]=a18;
  a19=arg[2]? arg[2][7] : 0;
  if (res[0]!=0) res[0][23]=a19;
  a20=arg[2]? arg[2][8] : 0;
  if (res[0]!=0) res[0][24]=a20;
  a21=arg[2]? arg[2][9] : 0;
  if (res[0]!=0) res[0][25]=a21;
  a22=arg[2]? arg[2][10] : 0;
  if (res[0]!=0) res[0][26]=a22;
  a23=arg[2]? arg[2][11] : 0;
  if (res[0]!=0) res[0][27]=a23;
  a24=arg[2]? arg[2][12] : 0;
  if (res[0]!=0) res[0][28]=a24;
  a25=arg[2]? arg[2][13] : 0;
  if (res[0]!=0) res[0][29]=a25;
  a26=arg[2]? arg[2][14] : 0;
  if (res[0]!=0) res[0][30]=a26;
  a27=arg[2]? arg[2][15] : 0;
  if (res[0]!=0) res[0][31]=a27;
  a28=arg[2]? arg[2][16] : 0;
  if (res[0]!=0) res[0][32]=a28;
  a29=arg[2]? arg[2][17] : 0;
  if (res[0]!=0) res[0][33]=a29;
  a30=arg[2]? arg[2][18] : 0;
  if (res[0]!=0) res[0][34]=a30;
  a31=arg[2]? arg[2][19] : 0;
  if (res[0]!=0) res[0][35]=a31;
  a32=arg[2]? arg[2][20] : 0;
  if (res[0]!=0) res[0][36]=a32;
  a33=arg[2]? arg[2][21] : 0;
  if (res[0]!=0) res[0][37]=a33;
  a34=arg[2]? arg[2][22] : 0;
  if (res[0]!=0) res[0][38]=a34;
  a35=arg[2]? arg[2][23] : 0;
  if (res[0]!=0) res[0][39]=a35;
  a36=arg[3]? arg[3][0] : 0;
  if (res[0]!=0) res[0][40]=a36;
  a37=arg[3]? arg[3][1] : 0;
  if (res[0]!=0) res[0][41]=a37;
  a38=arg[3]? arg[3][2] : 0;
  if (res[0]!=0) res[0][42]=a38;
  a39=arg[3]? arg[3][3] : 0;
  if (res[0]!=0) res[0][43]=a39;
  a40=arg[3]? arg[3][4] : 0;
  if (res[0]!=0) res[0][44]=a40;
  a41=arg[3]? arg[3][5] : 0;
  if (res[0]!=0) res[0][45]=a41;
  a42=arg[3]? arg[3][6] : 0;
  if (res[0]!=0) res[0][46]=a42;
  a43=arg[3]? arg[3][7] : 0;
  if (res[0]!=0) res[0][47]=a43;
  a44=arg[3]? arg[3][8] : 0;
  if (res[0]!=0) res[0][48]=a44;
  a45=arg[4]? arg[4][0] : 0;
  if (res[0]!=0) res[0][49]=a45;
  a46=arg[4]? arg[4][1] : 0;
  if (res[0]!=0) res[0][50]=a46;
  a47=arg[4]? arg[4][2] : 0;
  if (res[0]!=0) res[0][51]=a47;
  a48=arg[4]? arg[4][3] : 0;
  if (res[0]!=0) res[0][52]=a48;
  a49=arg[4]? arg[4][4] : 0;
  if (res[0]!=0) res[0][53]=a49;
  a50=arg[4]? arg[4][5] : 0;
  if (res[0]!=0) res[0][54]=a50;
  a51=arg[4]? arg[4][6] : 0;
  if (res[0]!=0) res[0][55]=a51;
  a52=arg[4]? arg[4][7] : 0;
  if (res[0]!=0) res[0][56]=a52;
  a53=arg[4]? arg[4][8] : 0;
  if (res[0]!=0) res[0][57]=a53;
  a54=arg[5]? arg[5][0] : 0;
  if (res[0]!=0) res[0][58]=a54;
  a55=arg[5]? arg[5][1] : 0;
  if (res[0]!=0) res[0][59]=a55;
  a56=arg[5]? arg[5][2] : 0;
  if (res[0]!=0) res[0][60]=a56;
  a57=arg[5]? arg[5][3] : 0;
  if (res[0]!=0) res[0][61]=a57;
  a58=arg[5]? arg[5][4] : 0;
  if (res[0]!=0) res[0][62]=a58;
  a59=arg[5]? arg[5][5] : 0;
  if (res[0]!=0) res[0][63]=a59;
  a60=arg[5]? arg[5][6] : 0;
  if (res[0]!=0) res[0][64]=a60;
  a61=arg[5]? arg[5][7] : 0;
  if (res[0]!=0) res[0][65]=a61;
  a62=arg[5]? arg[5][8] : 0;
  if (res[0]!=0) res[0][66]=a62;
  a63=arg[6]? arg[6][0] : 0;
  if (res[0]!=0) res[0][67]=a63;
  a63=arg[6]? arg[6][1] : 0;
  if (res[0]!=0) res[0][68]=a63;
  a63=arg[6]? arg[6][2] : 0;
  if (res[0]!=0) res[0][69]=a63;
  a63=0.;
  a64=casadi_sq(a54);
  a65=casadi_sq(a55);
  a64=(a64+a65);
  a65=casadi_sq(a56);
  a64=(a64+a65);
  a65=-5.0000000000000000e-01;
  a64=pow(a64,a65);
  a56=(a56*a64);
  a66=(a63<=a56);
  a67=1.;
  a54=(a54*a64);
  a68=casadi_sq(a54);
  a69=(a67+a56);
  a70=(a68/a69);
  a70=(a67-a70);
  a70=(a66?a70:0);
  a71=(!a66);
  a72=(a67-a56);
  a68=(a68/a72);
  a68=(a67-a68);
  a68=(a71?a68:0);
  a70=(a70+a68);
  if (res[0]!=0) res[0][70]=a70;
  a55=(a55*a64);
  a64=(a54*a55);
  a68=(a64/a69);
  a68=(-a68);
  a68=(a66?a68:0);
  a64=(a64/a72);
  a73=(-a64);
  a73=(a71?a73:0);
  a73=(a68+a73);
  if (res[0]!=0) res[0][71]=a73;
  a74=(-a54);
  a74=(a66?a74:0);
  a75=(a71?a54:0);
  a74=(a74+a75);
  if (res[0]!=0) res[0][72]=a74;
  a64=(a71?a64:0);
  a68=(a68+a64);
  if (res[0]!=0) res[0][73]=a68;
  a64=casadi_sq(a55);
  a69=(a64/a69);
  a69=(a67-a69);
  a66=(a66?a69:0);
  a64=(a64/a72);
  a64=(a64-a67);
  a71=(a71?a64:0);
  a66=(a66+a71);
  if (res[0]!=0) res[0][74]=a66;
  a71=(-a55);
  if (res[0]!=0) res[0][75]=a71;
  if (res[0]!=0) res[0][76]=a54;
  if (res[0]!=0) res[0][77]=a55;
  if (res[0]!=0) res[0][78]=a56;
  a71=casadi_sq(a57);
  a64=casadi_sq(a58);
  a71=(a71+a64);
  a64=casadi_sq(a59);
  a71=(a71+a64);
  a71=pow(a71,a65);
  a59=(a59*a71);
  a64=(a63<=a59);
  a57=(a57*a71);
  a72=casadi_sq(a57);
  a69=(a67+a59);
  a75=(a72/a69);
  a75=(a67-a75);
  a75=(a64?a75:0);
  a76=(!a64);
  a77=(a67-a59);
  a72=(a72/a77);
  a72=(a67-a72);
  a72=(a76?a72:0);
  a75=(a75+a72);
  if (res[0]!=0) res[0][79]=a75;
  a58=(a58*a71);
  a71=(a57*a58);
  a72=(a71/a69);
  a72=(-a72);
  a72=(a64?a72:0);
  a71=(a71/a77);
  a78=(-a71);
  a78=(a76?a78:0);
  a78=(a72+a78);
  if (res[0]!=0) res[0][80]=a78;
  a79=(-a57);
  a79=(a64?a79:0);
  a80=(a76?a57:0);
  a79=(a79+a80);
  if (res[0]!=0) res[0][81]=a79;
  a71=(a76?a71:0);
  a72=(a72+a71);
  if (res[0]!=0) res[0][82]=a72;
  a71=casadi_sq(a58);
  a69=(a71/a69);
  a69=(a67-a69);
  a64=(a64?a69:0);
  a71=(a71/a77);
  a71=(a71-a67);
  a76=(a76?a71:0);
  a64=(a64+a76);
  if (res[0]!=0) res[0][83]=a64;
  a76=(-a58);
  if (res[0]!=0) res[0][84]=a76;
  if (res[0]!=0) res[0][85]=a57;
  if (res[0]!=0) res[0][86]=a58;
  if (res[0]!=0) res[0][87]=a59;
  a76=casadi_sq(a60);
  a71=casadi_sq(a61);
  a76=(a76+a71);
  a71=casadi_sq(a62);
  a76=(a76+a71);
  a76=pow(a76,a65);
  a62=(a62*a76);
  a63=(a63<=a62);
  a60=(a60*a76);
  a65=casadi_sq(a60);
  a71=(a67+a62);
  a77=(a65/a71);
  a77=(a67-a77);
  a77=(a63?a77:0);
  a69=(!a63);
  a80=(a67-a62);
  a65=(a65/a80);
  a65=(a67-a65);
  a65=(a69?a65:0);
  a77=(a77+a65);
  if (res[0]!=0) res[0][88]=a77;
  a61=(a61*a76);
  a76=(a60*a61);
  a65=(a76/a71);
  a65=(-a65);
  a65=(a63?a65:0);
  a76=(a76/a80);
  a81=(-a76);
  a81=(a69?a81:0);
  a81=(a65+a81);
  if (res[0]!=0) res[0][89]=a81;
  a82=(-a60);
  a82=(a63?a82:0);
  a83=(a69?a60:0);
  a82=(a82+a83);
  if (res[0]!=0) res[0][90]=a82;
  a76=(a69?a76:0);
  a65=(a65+a76);
  if (res[0]!=0) res[0][91]=a65;
  a76=casadi_sq(a61);
  a71=(a76/a71);
  a71=(a67-a71);
  a63=(a63?a71:0);
  a76=(a76/a80);
  a76=(a76-a67);
  a69=(a69?a76:0);
  a63=(a63+a69);
  if (res[0]!=0) res[0][92]=a63;
  a69=(-a61);
  if (res[0]!=0) res[0][93]=a69;
  if (res[0]!=0) res[0][94]=a60;
  if (res[0]!=0) res[0][95]=a61;
  if (res[0]!=0) res[0][96]=a62;
  a69=cos(a46);
  a76=cos(a47);
  a67=(a69*a76);
  a80=(a67*a70);
  a46=sin(a46);
  a71=(a76*a46);
  a83=sin(a45);
  a71=(a71*a83);
  a45=cos(a45);
  a47=sin(a47);
  a84=(a45*a47);
  a71=(a71-a84);
  a84=(a71*a73);
  a80=(a80+a84);
  a84=(a83*a47);
  a85=(a45*a76);
  a86=(a85*a46);
  a84=(a84+a86);
  a86=(a84*a74);
  a80=(a80+a86);
  if (res[0]!=0) res[0][97]=a80;
  a80=(a69*a47);
  a86=(a80*a70);
  a87=(a46*a83);
  a87=(a87*a47);
  a85=(a85+a87);
  a87=(a85*a73);
  a86=(a86+a87);
  a87=(a45*a46);
  a87=(a87*a47);
  a76=(a76*a83);
  a87=(a87-a76);
  a76=(a87*a74);
  a86=(a86+a76);
  if (res[0]!=0) res[0][98]=a86;
  a83=(a69*a83);
  a86=(a83*a73);
  a76=(a46*a70);
  a86=(a86-a76);
  a69=(a69*a45);
  a45=(a69*a74);
  a86=(a86+a45);
  if (res[0]!=0) res[0][99]=a86;
  a86=(a67*a68);
  a45=(a71*a66);
  a86=(a86+a45);
  a45=(a84*a55);
  a86=(a86-a45);
  if (res[0]!=0) res[0][100]=a86;
  a86=(a80*a68);
  a45=(a85*a66);
  a86=(a86+a45);
  a45=(a87*a55);
  a86=(a86-a45);
  if (res[0]!=0) res[0][101]=a86;
  a86=(a83*a66);
  a45=(a46*a68);
  a86=(a86-a45);
  a45=(a69*a55);
  a86=(a86-a45);
  if (res[0]!=0) res[0][102]=a86;
  a67=(a67*a54);
  a71=(a71*a55);
  a67=(a67+a71);
  a84=(a84*a56);
  a67=(a67+a84);
  if (res[0]!=0) res[0][103]=a67;
  a80=(a80*a54);
  a85=(a85*a55);
  a80=(a80+a85);
  a87=(a87*a56);
  a80=(a80+a87);
  if (res[0]!=0) res[0][104]=a80;
  a83=(a83*a55);
  a46=(a46*a54);
  a83=(a83-a46);
  a69=(a69*a56);
  a83=(a83+a69);
  if (res[0]!=0) res[0][105]=a83;
  a83=cos(a49);
  a69=cos(a50);
  a46=(a83*a69);
  a80=(a46*a70);
  a50=sin(a50);
  a87=(a83*a50);
  a85=(a87*a73);
  a80=(a80+a85);
  a49=sin(a49);
  a85=(a49*a74);
  a80=(a80-a85);
  a85=(a75*a80);
  a67=(a69*a49);
  a84=sin(a48);
  a67=(a67*a84);
  a48=cos(a48);
  a71=(a48*a50);
  a67=(a67-a71);
  a71=(a67*a70);
  a86=(a48*a69);
  a45=(a49*a84);
  a45=(a45*a50);
  a45=(a86+a45);
  a76=(a45*a73);
  a71=(a71+a76);
  a76=(a83*a84);
  a47=(a76*a74);
  a71=(a71+a47);
  a47=(a78*a71);
  a85=(a85+a47);
  a47=(a84*a50);
  a86=(a86*a49);
  a47=(a47+a86);
  a86=(a47*a70);
  a88=(a48*a49);
  a88=(a88*a50);
  a69=(a69*a84);
  a88=(a88-a69);
  a69=(a88*a73);
  a86=(a86+a69);
  a83=(a83*a48);
  a48=(a83*a74);
  a86=(a86+a48);
  a48=(a79*a86);
  a85=(a85+a48);
  if (res[0]!=0) res[0][106]=a85;
  a85=(a46*a68);
  a48=(a87*a66);
  a85=(a85+a48);
  a48=(a49*a55);
  a85=(a85+a48);
  a48=(a75*a85);
  a69=(a67*a68);
  a84=(a45*a66);
  a69=(a69+a84);
  a84=(a76*a55);
  a69=(a69-a84);
  a84=(a78*a69);
  a48=(a48+a84);
  a84=(a47*a68);
  a50=(a88*a66);
  a84=(a84+a50);
  a50=(a83*a55);
  a84=(a84-a50);
  a50=(a79*a84);
  a48=(a48+a50);
  if (res[0]!=0) res[0][107]=a48;
  a46=(a46*a54);
  a87=(a87*a55);
  a46=(a46+a87);
  a49=(a49*a56);
  a46=(a46-a49);
  a49=(a75*a46);
  a67=(a67*a54);
  a45=(a45*a55);
  a67=(a67+a45);
  a76=(a76*a56);
  a67=(a67+a76);
  a76=(a78*a67);
  a49=(a49+a76);
  a47=(a47*a54);
  a88=(a88*a55);
  a47=(a47+a88);
  a83=(a83*a56);
  a47=(a47+a83);
  a83=(a79*a47);
  a49=(a49+a83);
  if (res[0]!=0) res[0][108]=a49;
  a49=(a72*a80);
  a83=(a64*a71);
  a49=(a49+a83);
  a83=(a58*a86);
  a49=(a49-a83);
  if (res[0]!=0) res[0][109]=a49;
  a49=(a72*a85);
  a83=(a64*a69);
  a49=(a49+a83);
  a83=(a58*a84);
  a49=(a49-a83);
  if (res[0]!=0) res[0][110]=a49;
  a49=(a72*a46);
  a83=(a64*a67);
  a49=(a49+a83);
  a83=(a58*a47);
  a49=(a49-a83);
  if (res[0]!=0) res[0][111]=a49;
  a80=(a57*a80);
  a71=(a58*a71);
  a80=(a80+a71);
  a86=(a59*a86);
  a80=(a80+a86);
  if (res[0]!=0) res[0][112]=a80;
  a85=(a57*a85);
  a69=(a58*a69);
  a85=(a85+a69);
  a84=(a59*a84);
  a85=(a85+a84);
  if (res[0]!=0) res[0][113]=a85;
  a46=(a57*a46);
  a67=(a58*a67);
  a46=(a46+a67);
  a47=(a59*a47);
  a46=(a46+a47);
  if (res[0]!=0) res[0][114]=a46;
  a46=cos(a52);
  a47=cos(a53);
  a67=(a46*a47);
  a85=(a67*a75);
  a53=sin(a53);
  a84=(a46*a53);
  a69=(a84*a78);
  a85=(a85+a69);
  a52=sin(a52);
  a69=(a52*a79);
  a85=(a85-a69);
  a69=(a77*a85);
  a80=(a47*a52);
  a86=sin(a51);
  a80=(a80*a86);
  a51=cos(a51);
  a71=(a51*a53);
  a80=(a80-a71);
  a71=(a80*a75);
  a49=(a51*a47);
  a83=(a52*a86);
  a83=(a83*a53);
  a83=(a49+a83);
  a88=(a83*a78);
  a71=(a71+a88);
  a88=(a46*a86);
  a76=(a88*a79);
  a71=(a71+a76);
  a76=(a81*a71);
  a69=(a69+a76);
  a76=(a86*a53);
  a49=(a49*a52);
  a76=(a76+a49);
  a49=(a76*a75);
  a45=(a51*a52);
  a45=(a45*a53);
  a47=(a47*a86);
  a45=(a45-a47);
  a47=(a45*a78);
  a49=(a49+a47);
  a46=(a46*a51);
  a51=(a46*a79);
  a49=(a49+a51);
  a51=(a82*a49);
  a69=(a69+a51);
  if (res[0]!=0) res[0][115]=a69;
  a69=(a67*a72);
  a51=(a84*a64);
  a69=(a69+a51);
  a51=(a52*a58);
  a69=(a69+a51);
  a51=(a77*a69);
  a47=(a80*a72);
  a86=(a83*a64);
  a47=(a47+a86);
  a86=(a88*a58);
  a47=(a47-a86);
  a86=(a81*a47);
  a51=(a51+a86);
  a86=(a76*a72);
  a53=(a45*a64);
  a86=(a86+a53);
  a53=(a46*a58);
  a86=(a86-a53);
  a53=(a82*a86);
  a51=(a51+a53);
  if (res[0]!=0) res[0][116]=a51;
  a67=(a67*a57);
  a84=(a84*a58);
  a67=(a67+a84);
  a52=(a52*a59);
  a67=(a67-a52);
  a52=(a77*a67);
  a80=(a80*a57);
  a83=(a83*a58);
  a80=(a80+a83);
  a88=(a88*a59);
  a80=(a80+a88);
  a88=(a81*a80);
  a52=(a52+a88);
  a76=(a76*a57);
  a45=(a45*a58);
  a76=(a76+a45);
  a46=(a46*a59);
  a76=(a76+a46);
  a46=(a82*a76);
  a52=(a52+a46);
  if (res[0]!=0) res[0][117]=a52;
  a52=(a65*a85);
  a46=(a63*a71);
  a52=(a52+a46);
  a46=(a61*a49);
  a52=(a52-a46);
  if (res[0]!=0) res[0][118]=a52;
  a52=(a65*a69);
  a46=(a63*a47);
  a52=(a52+a46);
  a46=(a61*a86);
  a52=(a52-a46);
  if (res[0]!=0) res[0][119]=a52;
  a52=(a65*a67);
  a46=(a63*a80);
  a52=(a52+a46);
  a46=(a61*a76);
  a52=(a52-a46);
  if (res[0]!=0) res[0][120]=a52;
  a85=(a60*a85);
  a71=(a61*a71);
  a85=(a85+a71);
  a49=(a62*a49);
  a85=(a85+a49);
  if (res[0]!=0) res[0][121]=a85;
  a69=(a60*a69);
  a47=(a61*a47);
  a69=(a69+a47);
  a86=(a62*a86);
  a69=(a69+a86);
  if (res[0]!=0) res[0][122]=a69;
  a67=(a60*a67);
  a80=(a61*a80);
  a67=(a67+a80);
  a76=(a62*a76);
  a67=(a67+a76);
  if (res[0]!=0) res[0][123]=a67;
  if (res[0]!=0) res[0][124]=a36;
  if (res[0]!=0) res[0][125]=a37;
  if (res[0]!=0) res[0][126]=a38;
  a38=(a70*a39);
  a37=(a73*a40);
  a38=(a38+a37);
  a37=(a74*a41);
  a38=(a38+a37);
  if (res[0]!=0) res[0][127]=a38;
  a38=(a68*a39);
  a37=(a66*a40);
  a38=(a38+a37);
  a37=(a55*a41);
  a38=(a38-a37);
  if (res[0]!=0) res[0][128]=a38;
  a39=(a54*a39);
  a40=(a55*a40);
  a39=(a39+a40);
  a41=(a56*a41);
  a39=(a39+a41);
  if (res[0]!=0) res[0][129]=a39;
  a39=(a75*a42);
  a41=(a78*a43);
  a39=(a39+a41);
  a41=(a79*a44);
  a39=(a39+a41);
  if (res[0]!=0) res[0][130]=a39;
  a39=(a72*a42);
  a41=(a64*a43);
  a39=(a39+a41);
  a41=(a58*a44);
  a39=(a39-a41);
  if (res[0]!=0) res[0][131]=a39;
  a42=(a57*a42);
  a43=(a58*a43);
  a42=(a42+a43);
  a44=(a59*a44);
  a42=(a42+a44);
  if (res[0]!=0) res[0][132]=a42;
  if (res[0]!=0) res[0][133]=a00;
  if (res[0]!=0) res[0][134]=a01;
  if (res[0]!=0) res[0][135]=a02;
  a02=(a70*a03);
  a01=(a73*a04);
  a02=(a02+a01);
  a01=(a74*a05);
  a02=(a02+a01);
  if (res[0]!=0) res[0][136]=a02;
  a02=(a68*a03);
  a01=(a66*a04);
  a02=(a02+a01);
  a01=(a55*a05);
  a02=(a02-a01);
  if (res[0]!=0) res[0][137]=a02;
  a03=(a54*a03);
  a04=(a55*a04);
  a03=(a03+a04);
  a05=(a56*a05);
  a03=(a03+a05);
  if (res[0]!=0) res[0][138]=a03;
  a03=(a75*a06);
  a05=(a78*a07);
  a03=(a03+a05);
  a05=(a79*a08);
  a03=(a03+a05);
  if (res[0]!=0) res[0][139]=a03;
  a03=(a72*a06);
  a05=(a64*a07);
  a03=(a03+a05);
  a05=(a58*a08);
  a03=(a03-a05);
  if (res[0]!=0) res[0][140]=a03;
  a06=(a57*a06);
  a07=(a58*a07);
  a06=(a06+a07);
  a08=(a59*a08);
  a06=(a06+a08);
  if (res[0]!=0) res[0][141]=a06;
  a06=(a77*a09);
  a08=(a81*a10);
  a06=(a06+a08);
  a08=(a82*a11);
  a06=(a06+a08);
  if (res[0]!=0) res[0][142]=a06;
  a06=(a65*a09);
  a08=(a63*a10);
  a06=(a06+a08);
  a08=(a61*a11);
  a06=(a06-a08);
  if (res[0]!=0) res[0][143]=a06;
  a09=(a60*a09);
  a10=(a61*a10);
  a09=(a09+a10);
  a11=(a62*a11);
  a09=(a09+a11);
  if (res[0]!=0) res[0][144]=a09;
  if (res[0]!=0) res[0][145]=a12;
  if (res[0]!=0) res[0][146]=a13;
  if (res[0]!=0) res[0][147]=a14;
  if (res[0]!=0) res[0][148]=a15;
  if (res[0]!=0) res[0][149]=a16;
  if (res[0]!=0) res[0][150]=a17;
  a17=(a18*a70);
  a16=(a21*a73);
  a17=(a17+a16);
  a16=(a22*a74);
  a17=(a17+a16);
  a16=(a70*a17);
  a15=(a21*a70);
  a14=(a19*a73);
  a15=(a15+a14);
  a14=(a23*a74);
  a15=(a15+a14);
  a14=(a73*a15);
  a16=(a16+a14);
  a70=(a22*a70);
  a73=(a23*a73);
  a70=(a70+a73);
  a73=(a20*a74);
  a70=(a70+a73);
  a74=(a74*a70);
  a16=(a16+a74);
  if (res[0]!=0) res[0][151]=a16;
  a16=(a18*a68);
  a74=(a21*a66);
  a16=(a16+a74);
  a74=(a22*a55);
  a16=(a16-a74);
  a74=(a68*a16);
  a73=(a21*a68);
  a14=(a19*a66);
  a73=(a73+a14);
  a14=(a23*a55);
  a73=(a73-a14);
  a13=(a66*a73);
  a74=(a74+a13);
  a13=(a22*a68);
  a12=(a23*a66);
  a13=(a13+a12);
  a12=(a20*a55);
  a13=(a13-a12);
  a12=(a55*a13);
  a74=(a74-a12);
  if (res[0]!=0) res[0][152]=a74;
  a18=(a18*a54);
  a74=(a21*a55);
  a18=(a18+a74);
  a74=(a22*a56);
  a18=(a18+a74);
  a18=(a54*a18);
  a21=(a21*a54);
  a19=(a19*a55);
  a21=(a21+a19);
  a23=(a23*a56);
  a21=(a21+a23);
  a21=(a55*a21);
  a18=(a18+a21);
  a22=(a22*a54);
  a22=(a22+a14);
  a20=(a20*a56);
  a22=(a22+a20);
  a22=(a56*a22);
  a18=(a18+a22);
  if (res[0]!=0) res[0][153]=a18;
  a68=(a68*a17);
  a66=(a66*a15);
  a68=(a68+a66);
  a66=(a55*a70);
  a68=(a68-a66);
  if (res[0]!=0) res[0][154]=a68;
  a17=(a54*a17);
  a15=(a55*a15);
  a17=(a17+a15);
  a70=(a56*a70);
  a17=(a17+a70);
  if (res[0]!=0) res[0][155]=a17;
  a54=(a54*a16);
  a55=(a55*a73);
  a54=(a54+a55);
  a56=(a56*a13);
  a54=(a54+a56);
  if (res[0]!=0) res[0][156]=a54;
  a54=(a24*a75);
  a56=(a27*a78);
  a54=(a54+a56);
  a56=(a28*a79);
  a54=(a54+a56);
  a56=(a75*a54);
  a13=(a27*a75);
  a55=(a25*a78);
  a13=(a13+a55);
  a55=(a29*a79);
  a13=(a13+a55);
  a55=(a78*a13);
  a56=(a56+a55);
  a75=(a28*a75);
  a78=(a29*a78);
  a75=(a75+a78);
  a78=(a26*a79);
  a75=(a75+a78);
  a79=(a79*a75);
  a56=(a56+a79);
  if (res[0]!=0) res[0][157]=a56;
  a56=(a24*a72);
  a79=(a27*a64);
  a56=(a56+a79);
  a79=(a28*a58);
  a56=(a56-a79);
  a79=(a72*a56);
  a78=(a27*a72);
  a55=(a25*a64);
  a78=(a78+a55);
  a55=(a29*a58);
  a78=(a78-a55);
  a73=(a64*a78);
  a79=(a79+a73);
  a73=(a28*a72);
  a16=(a29*a64);
  a73=(a73+a16);
  a16=(a26*a58);
  a73=(a73-a16);
  a16=(a58*a73);
  a79=(a79-a16);
  if (res[0]!=0) res[0][158]=a79;
  a24=(a24*a57);
  a79=(a27*a58);
  a24=(a24+a79);
  a79=(a28*a59);
  a24=(a24+a79);
  a24=(a57*a24);
  a27=(a27*a57);
  a25=(a25*a58);
  a27=(a27+a25);
  a29=(a29*a59);
  a27=(a27+a29);
  a27=(a58*a27);
  a24=(a24+a27);
  a28=(a28*a57);
  a28=(a28+a55);
  a26=(a26*a59);
  a28=(a28+a26);
  a28=(a59*a28);
  a24=(a24+a28);
  if (res[0]!=0) res[0][159]=a24;
  a72=(a72*a54);
  a64=(a64*a13);
  a72=(a72+a64);
  a64=(a58*a75);
  a72=(a72-a64);
  if (res[0]!=0) res[0][160]=a72;
  a54=(a57*a54);
  a13=(a58*a13);
  a54=(a54+a13);
  a75=(a59*a75);
  a54=(a54+a75);
  if (res[0]!=0) res[0][161]=a54;
  a57=(a57*a56);
  a58=(a58*a78);
  a57=(a57+a58);
  a59=(a59*a73);
  a57=(a57+a59);
  if (res[0]!=0) res[0][162]=a57;
  a57=(a30*a77);
  a59=(a33*a81);
  a57=(a57+a59);
  a59=(a34*a82);
  a57=(a57+a59);
  a59=(a77*a57);
  a73=(a33*a77);
  a58=(a31*a81);
  a73=(a73+a58);
  a58=(a35*a82);
  a73=(a73+a58);
  a58=(a81*a73);
  a59=(a59+a58);
  a77=(a34*a77);
  a81=(a35*a81);
  a77=(a77+a81);
  a81=(a32*a82);
  a77=(a77+a81);
  a82=(a82*a77);
  a59=(a59+a82);
  if (res[0]!=0) res[0][163]=a59;
  a59=(a30*a65);
  a82=(a33*a63);
  a59=(a59+a82);
  a82=(a34*a61);
  a59=(a59-a82);
  a82=(a65*a59);
  a81=(a33*a65);
  a58=(a31*a63);
  a81=(a81+a58);
  a58=(a35*a61);
  a81=(a81-a58);
  a78=(a63*a81);
  a82=(a82+a78);
  a78=(a34*a65);
  a56=(a35*a63);
  a78=(a78+a56);
  a56=(a32*a61);
  a78=(a78-a56);
  a56=(a61*a78);
  a82=(a82-a56);
  if (res[0]!=0) res[0][164]=a82;
  a30=(a30*a60);
  a82=(a33*a61);
  a30=(a30+a82);
  a82=(a34*a62);
  a30=(a30+a82);
  a30=(a60*a30);
  a33=(a33*a60);
  a31=(a31*a61);
  a33=(a33+a31);
  a35=(a35*a62);
  a33=(a33+a35);
  a33=(a61*a33);
  a30=(a30+a33);
  a34=(a34*a60);
  a34=(a34+a58);
  a32=(a32*a62);
  a34=(a34+a32);
  a34=(a62*a34);
  a30=(a30+a34);
  if (res[0]!=0) res[0][165]=a30;
  a65=(a65*a57);
  a63=(a63*a73);
  a65=(a65+a63);
  a63=(a61*a77);
  a65=(a65-a63);
  if (res[0]!=0) res[0][166]=a65;
  a57=(a60*a57);
  a73=(a61*a73);
  a57=(a57+a73);
  a77=(a62*a77);
  a57=(a57+a77);
  if (res[0]!=0) res[0][167]=a57;
  a60=(a60*a59);
  a61=(a61*a81);
  a60=(a60+a61);
  a62=(a62*a78);
  a60=(a60+a62);
  if (res[0]!=0) res[0][168]=a60;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_derived_parameters_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_derived_parameters_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_derived_parameters_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_derived_parameters_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_derived_parameters_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_derived_parameters_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_derived_parameters_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_mass";
    case 1: return "link_com";
    case 2: return "link_inertia";
    case 3: return "joint_xyz";
    case 4: return "joint_rpy";
    case 5: return "joint_axis";
    case 6: return "gravity";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_derived_parameters_name_out(casadi_int i) {
  switch (i) {
    case 0: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_derived_parameters_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_derived_parameters_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_derived_parameters_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_derived_parameters(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[7];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 90);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 7; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    r[0] = res[0] + i * 169;
    if (snakecg_sp3_derived_parameters(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
