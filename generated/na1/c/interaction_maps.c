/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for interaction_maps() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 69ac8a580508aa26bce28f4a88e0f77c0b28e33b1f2694eb6cf4bbbcae64a5df
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_interaction_maps_ ## ID
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

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na1_interaction_maps_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};
static const casadi_int casadi_s5[3] = {3, 3, 1};
static const casadi_int casadi_s6[3] = {4, 3, 1};
static const casadi_int casadi_s7[3] = {3, 7, 1};
static const casadi_int casadi_s8[3] = {7, 7, 1};

/* snakecg_na1_interaction_maps:(q[4],K[16],contact_link[2],side,object_mass,object_inertia,q_obj[3],rho[2],wheel_offset[2],free[3],lam_fixed[3],regularization)->(lam_from_tau[3],lam_from_f_obj[3x3],lam_offset[3],qdd_from_tau[4],qdd_from_f_obj[4x3],qdd_offset[4],a_obj_from_tau[3],a_obj_from_f_obj[3x3],a_obj_offset[3],w_from_tau[3],w_from_f_obj[3x3],w_offset[3],xi_tau,omega_tau,lambda_form_tau,input_metric,projector_constrained[3x7],projector_orthogonal[7x7],delassus[3x3],pivot_ratio) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87;
  a00=arg[9]? arg[9][0] : 0;
  a01=arg[3]? arg[3][0] : 0;
  a02=arg[1]? arg[1][6] : 0;
  a03=arg[2]? arg[2][0] : 0;
  a04=(a02*a03);
  a05=arg[1]? arg[1][7] : 0;
  a06=arg[2]? arg[2][1] : 0;
  a07=(a05*a06);
  a04=(a04+a07);
  a07=(a01*a04);
  a08=arg[0]? arg[0][2] : 0;
  a09=(a08*a03);
  a10=arg[0]? arg[0][3] : 0;
  a10=(a10+a08);
  a11=(a10*a06);
  a09=(a09+a11);
  a11=sin(a09);
  a12=(a11*a01);
  a13=arg[6]? arg[6][2] : 0;
  a14=cos(a13);
  a15=arg[7]? arg[7][1] : 0;
  a16=(a14*a15);
  a13=sin(a13);
  a17=arg[7]? arg[7][0] : 0;
  a18=(a13*a17);
  a16=(a16+a18);
  a18=arg[6]? arg[6][1] : 0;
  a18=(a16+a18);
  a11=(a11*a04);
  a18=(a18+a11);
  a11=arg[0]? arg[0][1] : 0;
  a19=(a11*a03);
  a20=arg[1]? arg[1][2] : 0;
  a20=(a20-a02);
  a02=sin(a08);
  a21=(a20*a02);
  a21=(a11+a21);
  a22=sin(a10);
  a23=(a22*a05);
  a21=(a21+a23);
  a24=(a21*a06);
  a19=(a19+a24);
  a18=(a18-a19);
  a18=(a12*a18);
  a07=(a07-a18);
  a09=cos(a09);
  a18=(a09*a01);
  a14=(a14*a17);
  a13=(a13*a15);
  a14=(a14-a13);
  a13=arg[6]? arg[6][0] : 0;
  a13=(a14+a13);
  a04=(a09*a04);
  a13=(a13+a04);
  a04=arg[0]? arg[0][0] : 0;
  a15=(a04*a03);
  a08=cos(a08);
  a20=(a08*a20);
  a20=(a04+a20);
  a10=cos(a10);
  a05=(a10*a05);
  a20=(a20+a05);
  a17=(a20*a06);
  a15=(a15+a17);
  a13=(a13-a15);
  a13=(a18*a13);
  a07=(a07-a13);
  a13=(a07*a06);
  a15=(a06*a23);
  a15=(a12*a15);
  a17=(a06*a05);
  a17=(a18*a17);
  a15=(a15+a17);
  a13=(a13-a15);
  a15=arg[1]? arg[1][10] : 0;
  a17=(a15*a22);
  a19=arg[1]? arg[1][8] : 0;
  a24=(a17/a19);
  a03=(a03+a06);
  a25=(a12*a03);
  a26=(a24*a25);
  a26=(a13+a26);
  a15=(a15*a10);
  a27=(a15/a19);
  a28=(a18*a03);
  a29=(a27*a28);
  a26=(a26+a29);
  a29=(a08*a10);
  a30=(a02*a22);
  a29=(a29+a30);
  a30=arg[1]? arg[1][12] : 0;
  a29=(a29*a30);
  a30=arg[1]? arg[1][15] : 0;
  a31=(a29+a30);
  a32=arg[1]? arg[1][9] : 0;
  a33=(a32*a02);
  a33=(a17+a33);
  a34=(a33/a19);
  a35=(a24*a34);
  a35=(a35*a19);
  a35=(a31-a35);
  a32=(a32*a08);
  a32=(a15+a32);
  a36=(a32/a19);
  a37=(a27*a36);
  a37=(a37*a19);
  a35=(a35-a37);
  a37=arg[1]? arg[1][14] : 0;
  a29=(a29+a37);
  a29=(a29+a31);
  a37=casadi_sq(a34);
  a37=(a37*a19);
  a37=(a29-a37);
  a38=casadi_sq(a36);
  a38=(a38*a19);
  a37=(a37-a38);
  a35=(a35/a37);
  a11=(a11-a21);
  a21=(a06*a11);
  a21=(a12*a21);
  a20=(a20-a04);
  a06=(a06*a20);
  a06=(a18*a06);
  a21=(a21-a06);
  a07=(a07*a03);
  a21=(a21+a07);
  a07=(a34*a25);
  a07=(a21+a07);
  a03=(a36*a28);
  a07=(a07+a03);
  a03=(a35*a07);
  a26=(a26-a03);
  a03=casadi_sq(a24);
  a03=(a03*a19);
  a03=(a30-a03);
  a06=casadi_sq(a27);
  a06=(a06*a19);
  a03=(a03-a06);
  a06=casadi_sq(a35);
  a06=(a06*a37);
  a03=(a03-a06);
  a26=(a26/a03);
  a06=(a00*a26);
  a04=(a25/a19);
  a07=(a07/a37);
  a38=(a35*a26);
  a07=(a07-a38);
  a38=(a34*a07);
  a04=(a04+a38);
  a38=(a24*a26);
  a04=(a04+a38);
  a38=(a25*a04);
  a39=(a28/a19);
  a40=(a36*a07);
  a39=(a39+a40);
  a40=(a27*a26);
  a39=(a39+a40);
  a40=(a28*a39);
  a38=(a38+a40);
  a40=(a21*a07);
  a38=(a38+a40);
  a40=(a13*a26);
  a38=(a38+a40);
  a40=arg[4]? arg[4][0] : 0;
  a41=(a12/a40);
  a42=(a12*a41);
  a43=(a18/a40);
  a44=(a18*a43);
  a42=(a42+a44);
  a09=(a09*a14);
  a09=(a09*a01);
  a16=(a12*a16);
  a09=(a09+a16);
  a16=arg[5]? arg[5][0] : 0;
  a01=(a09/a16);
  a14=(a09*a01);
  a42=(a42+a14);
  a38=(a38+a42);
  a42=(a00*a38);
  a14=(a42*a00);
  a44=1.;
  a45=(a44-a00);
  a14=(a14+a45);
  a46=arg[11]? arg[11][0] : 0;
  a47=(a46*a00);
  a14=(a14+a47);
  a47=(a06/a14);
  a48=arg[9]? arg[9][1] : 0;
  a49=arg[8]? arg[8][0] : 0;
  a50=(a49*a07);
  a51=(a02*a04);
  a52=(a08*a39);
  a51=(a51+a52);
  a50=(a50-a51);
  a51=(a48*a50);
  a52=(a51*a00);
  a52=(a52/a14);
  a53=(a24*a02);
  a54=(a27*a08);
  a53=(a53+a54);
  a54=(a34*a02);
  a54=(a49-a54);
  a55=(a36*a08);
  a54=(a54-a55);
  a55=(a35*a54);
  a53=(a53+a55);
  a53=(a53/a03);
  a55=(a48*a53);
  a56=(a52*a06);
  a55=(a55+a56);
  a56=(a08/a19);
  a54=(a54/a37);
  a57=(a35*a53);
  a54=(a54+a57);
  a57=(a36*a54);
  a56=(a56-a57);
  a57=(a27*a53);
  a56=(a56+a57);
  a57=(a08*a56);
  a58=(a34*a54);
  a59=(a02/a19);
  a58=(a58-a59);
  a59=(a24*a53);
  a58=(a58-a59);
  a59=(a02*a58);
  a57=(a57-a59);
  a59=(a49*a54);
  a57=(a57+a59);
  a59=(a48*a57);
  a60=(a59*a48);
  a61=(a44-a48);
  a60=(a60+a61);
  a62=(a46*a48);
  a60=(a60+a62);
  a62=casadi_sq(a52);
  a62=(a62*a14);
  a62=(a60-a62);
  a63=(a55/a62);
  a64=arg[9]? arg[9][2] : 0;
  a65=(a10*a56);
  a66=(a22*a58);
  a65=(a65-a66);
  a20=(a10*a20);
  a11=(a22*a11);
  a20=(a20-a11);
  a11=arg[8]? arg[8][1] : 0;
  a20=(a20+a11);
  a66=(a20*a54);
  a65=(a65+a66);
  a23=(a22*a23);
  a05=(a10*a05);
  a23=(a23+a05);
  a23=(a23+a11);
  a11=(a23*a53);
  a65=(a65-a11);
  a11=(a64*a65);
  a05=(a11*a48);
  a66=(a20*a07);
  a67=(a22*a04);
  a68=(a10*a39);
  a67=(a67+a68);
  a66=(a66-a67);
  a67=(a23*a26);
  a66=(a66+a67);
  a67=(a64*a66);
  a68=(a67*a00);
  a68=(a68/a14);
  a69=(a68*a52);
  a69=(a69*a14);
  a05=(a05-a69);
  a05=(a05/a62);
  a69=(a24*a22);
  a69=(a23-a69);
  a70=(a27*a10);
  a69=(a69-a70);
  a70=(a34*a22);
  a70=(a20-a70);
  a71=(a36*a10);
  a70=(a70-a71);
  a71=(a35*a70);
  a69=(a69-a71);
  a69=(a69/a03);
  a71=(a64*a69);
  a06=(a68*a06);
  a71=(a71-a06);
  a55=(a05*a55);
  a71=(a71+a55);
  a55=(a10/a19);
  a70=(a70/a37);
  a37=(a35*a69);
  a70=(a70-a37);
  a37=(a36*a70);
  a55=(a55-a37);
  a37=(a27*a69);
  a55=(a55-a37);
  a37=(a10*a55);
  a06=(a34*a70);
  a72=(a22/a19);
  a06=(a06-a72);
  a72=(a24*a69);
  a06=(a06+a72);
  a72=(a22*a06);
  a37=(a37-a72);
  a72=(a20*a70);
  a37=(a37+a72);
  a72=(a23*a69);
  a37=(a37+a72);
  a72=(a64*a37);
  a73=(a72*a64);
  a74=(a44-a64);
  a73=(a73+a74);
  a46=(a46*a64);
  a73=(a73+a46);
  a46=casadi_sq(a68);
  a46=(a46*a14);
  a46=(a73-a46);
  a75=casadi_sq(a05);
  a75=(a75*a62);
  a46=(a46-a75);
  a71=(a71/a46);
  a75=(a05*a71);
  a63=(a63+a75);
  a75=(a52*a63);
  a47=(a47+a75);
  a75=(a68*a71);
  a47=(a47-a75);
  a75=(-a47);
  if (res[0]!=0) res[0][0]=a75;
  if (res[0]!=0) res[0][1]=a63;
  a75=(-a71);
  if (res[0]!=0) res[0][2]=a75;
  a75=(a00*a41);
  a76=(a75/a14);
  a77=(a52*a75);
  a78=(a77/a62);
  a75=(a68*a75);
  a77=(a05*a77);
  a75=(a75-a77);
  a75=(a75/a46);
  a77=(a05*a75);
  a78=(a78-a77);
  a77=(a52*a78);
  a76=(a76+a77);
  a77=(a68*a75);
  a76=(a76+a77);
  if (res[1]!=0) res[1][0]=a76;
  a77=(-a78);
  if (res[1]!=0) res[1][1]=a77;
  a77=(-a75);
  if (res[1]!=0) res[1][2]=a77;
  a77=(a00*a43);
  a79=(a77/a14);
  a80=(a52*a77);
  a81=(a80/a62);
  a80=(a05*a80);
  a77=(a68*a77);
  a80=(a80-a77);
  a80=(a80/a46);
  a77=(a05*a80);
  a81=(a81+a77);
  a77=(a52*a81);
  a79=(a79+a77);
  a77=(a68*a80);
  a79=(a79-a77);
  a77=(-a79);
  if (res[1]!=0) res[1][3]=a77;
  if (res[1]!=0) res[1][4]=a81;
  a77=(-a80);
  if (res[1]!=0) res[1][5]=a77;
  a77=(a00*a01);
  a82=(a77/a14);
  a83=(a52*a77);
  a84=(a83/a62);
  a83=(a05*a83);
  a77=(a68*a77);
  a83=(a83-a77);
  a83=(a83/a46);
  a77=(a05*a83);
  a84=(a84+a77);
  a77=(a52*a84);
  a82=(a82+a77);
  a77=(a68*a83);
  a82=(a82-a77);
  a77=(-a82);
  if (res[1]!=0) res[1][6]=a77;
  if (res[1]!=0) res[1][7]=a84;
  a77=(-a83);
  if (res[1]!=0) res[1][8]=a77;
  a77=arg[10]? arg[10][0] : 0;
  a45=(a45*a77);
  a42=(a42*a45);
  a77=(a25*a58);
  a85=(a28*a56);
  a77=(a77-a85);
  a85=(a21*a54);
  a77=(a77+a85);
  a85=(a13*a53);
  a77=(a77-a85);
  a85=(a00*a77);
  a86=arg[10]? arg[10][1] : 0;
  a61=(a61*a86);
  a85=(a85*a61);
  a42=(a42+a85);
  a85=(a25*a06);
  a86=(a28*a55);
  a85=(a85-a86);
  a86=(a21*a70);
  a85=(a85+a86);
  a86=(a13*a69);
  a85=(a85+a86);
  a86=(a00*a85);
  a87=arg[10]? arg[10][2] : 0;
  a74=(a74*a87);
  a86=(a86*a74);
  a42=(a42+a86);
  a86=(a42/a14);
  a51=(a51*a45);
  a59=(a59*a61);
  a51=(a51+a59);
  a59=(a08*a55);
  a87=(a02*a06);
  a59=(a59-a87);
  a87=(a49*a70);
  a59=(a59+a87);
  a87=(a48*a59);
  a87=(a87*a74);
  a51=(a51+a87);
  a87=(a52*a42);
  a51=(a51-a87);
  a87=(a51/a62);
  a67=(a67*a45);
  a11=(a11*a61);
  a67=(a67+a11);
  a72=(a72*a74);
  a67=(a67+a72);
  a42=(a68*a42);
  a67=(a67-a42);
  a51=(a05*a51);
  a67=(a67-a51);
  a67=(a67/a46);
  a51=(a05*a67);
  a87=(a87-a51);
  a51=(a52*a87);
  a86=(a86-a51);
  a51=(a68*a67);
  a86=(a86-a51);
  a45=(a45-a86);
  if (res[2]!=0) res[2][0]=a45;
  a61=(a61-a87);
  if (res[2]!=0) res[2][1]=a61;
  a74=(a74-a67);
  if (res[2]!=0) res[2][2]=a74;
  a24=(a24/a03);
  a35=(a35/a03);
  a34=(a34*a35);
  a24=(a24-a34);
  a34=(a58*a63);
  a67=(a04*a47);
  a34=(a34-a67);
  a67=(a06*a71);
  a34=(a34-a67);
  a34=(a24+a34);
  if (res[3]!=0) res[3][0]=a34;
  a36=(a36*a35);
  a27=(a27/a03);
  a36=(a36-a27);
  a27=(a39*a47);
  a67=(a56*a63);
  a27=(a27+a67);
  a67=(a55*a71);
  a27=(a27-a67);
  a27=(a36+a27);
  if (res[3]!=0) res[3][1]=a27;
  a67=(a54*a63);
  a87=(a07*a47);
  a67=(a67-a87);
  a87=(a70*a71);
  a67=(a67-a87);
  a67=(a67-a35);
  if (res[3]!=0) res[3][2]=a67;
  a87=(1./a03);
  a86=(a26*a47);
  a51=(a53*a63);
  a86=(a86+a51);
  a51=(a69*a71);
  a86=(a86+a51);
  a86=(a87-a86);
  if (res[3]!=0) res[3][3]=a86;
  a51=(a04*a76);
  a42=(a58*a78);
  a51=(a51-a42);
  a42=(a06*a75);
  a51=(a51-a42);
  if (res[4]!=0) res[4][0]=a51;
  a51=(a39*a76);
  a42=(a56*a78);
  a51=(a51+a42);
  a42=(a55*a75);
  a51=(a51+a42);
  a51=(-a51);
  if (res[4]!=0) res[4][1]=a51;
  a51=(a07*a76);
  a42=(a54*a78);
  a51=(a51-a42);
  a42=(a70*a75);
  a51=(a51-a42);
  if (res[4]!=0) res[4][2]=a51;
  a51=(a26*a76);
  a42=(a53*a78);
  a51=(a51+a42);
  a42=(a69*a75);
  a51=(a51-a42);
  if (res[4]!=0) res[4][3]=a51;
  a51=(a58*a81);
  a42=(a04*a79);
  a51=(a51-a42);
  a42=(a06*a80);
  a51=(a51-a42);
  if (res[4]!=0) res[4][4]=a51;
  a51=(a39*a79);
  a42=(a56*a81);
  a51=(a51+a42);
  a42=(a55*a80);
  a51=(a51-a42);
  if (res[4]!=0) res[4][5]=a51;
  a51=(a54*a81);
  a42=(a07*a79);
  a51=(a51-a42);
  a42=(a70*a80);
  a51=(a51-a42);
  if (res[4]!=0) res[4][6]=a51;
  a51=(a26*a79);
  a42=(a53*a81);
  a51=(a51+a42);
  a42=(a69*a80);
  a51=(a51+a42);
  a51=(-a51);
  if (res[4]!=0) res[4][7]=a51;
  a51=(a58*a84);
  a42=(a04*a82);
  a51=(a51-a42);
  a42=(a06*a83);
  a51=(a51-a42);
  if (res[4]!=0) res[4][8]=a51;
  a51=(a39*a82);
  a42=(a56*a84);
  a51=(a51+a42);
  a42=(a55*a83);
  a51=(a51-a42);
  if (res[4]!=0) res[4][9]=a51;
  a51=(a54*a84);
  a42=(a07*a82);
  a51=(a51-a42);
  a42=(a70*a83);
  a51=(a51-a42);
  if (res[4]!=0) res[4][10]=a51;
  a51=(a26*a82);
  a42=(a53*a84);
  a51=(a51+a42);
  a42=(a69*a83);
  a51=(a51+a42);
  a51=(-a51);
  if (res[4]!=0) res[4][11]=a51;
  a51=(a04*a45);
  a42=(a58*a61);
  a51=(a51+a42);
  a42=(a06*a74);
  a51=(a51+a42);
  if (res[5]!=0) res[5][0]=a51;
  a51=(a56*a61);
  a42=(a39*a45);
  a51=(a51-a42);
  a42=(a55*a74);
  a51=(a51+a42);
  if (res[5]!=0) res[5][1]=a51;
  a51=(a07*a45);
  a42=(a54*a61);
  a51=(a51+a42);
  a42=(a70*a74);
  a51=(a51+a42);
  if (res[5]!=0) res[5][2]=a51;
  a26=(a26*a45);
  a53=(a53*a61);
  a26=(a26-a53);
  a69=(a69*a74);
  a26=(a26+a69);
  if (res[5]!=0) res[5][3]=a26;
  a26=(a41*a47);
  if (res[6]!=0) res[6][0]=a26;
  a69=(a43*a47);
  a53=(-a69);
  if (res[6]!=0) res[6][1]=a53;
  a53=(a01*a47);
  a51=(-a53);
  if (res[6]!=0) res[6][2]=a51;
  a51=(1./a40);
  a42=(a41*a76);
  a42=(a51-a42);
  if (res[7]!=0) res[7][0]=a42;
  a42=(a43*a76);
  if (res[7]!=0) res[7][1]=a42;
  a42=(a01*a76);
  if (res[7]!=0) res[7][2]=a42;
  a42=(a41*a79);
  if (res[7]!=0) res[7][3]=a42;
  a42=(a43*a79);
  a51=(a51-a42);
  if (res[7]!=0) res[7][4]=a51;
  a51=(a01*a79);
  a51=(-a51);
  if (res[7]!=0) res[7][5]=a51;
  a51=(a41*a82);
  if (res[7]!=0) res[7][6]=a51;
  a51=(a43*a82);
  a51=(-a51);
  if (res[7]!=0) res[7][7]=a51;
  a51=(1./a16);
  a42=(a01*a82);
  a51=(a51-a42);
  if (res[7]!=0) res[7][8]=a51;
  a51=(a41*a45);
  a51=(-a51);
  if (res[8]!=0) res[8][0]=a51;
  a51=(a43*a45);
  if (res[8]!=0) res[8][1]=a51;
  a51=(a01*a45);
  if (res[8]!=0) res[8][2]=a51;
  a51=(a25*a24);
  a42=(a28*a36);
  a51=(a51-a42);
  a42=(a21*a35);
  a51=(a51-a42);
  a42=(a13/a03);
  a51=(a51+a42);
  a42=(a77*a63);
  a72=(a38*a47);
  a42=(a42-a72);
  a72=(a85*a71);
  a42=(a42-a72);
  a51=(a51+a42);
  if (res[9]!=0) res[9][0]=a51;
  a51=(a08*a36);
  a42=(a02*a24);
  a51=(a51-a42);
  a42=(a49*a35);
  a51=(a51-a42);
  a42=(a57*a63);
  a72=(a50*a47);
  a42=(a42-a72);
  a72=(a59*a71);
  a42=(a42-a72);
  a51=(a51+a42);
  if (res[9]!=0) res[9][1]=a51;
  a36=(a10*a36);
  a24=(a22*a24);
  a36=(a36-a24);
  a35=(a20*a35);
  a36=(a36-a35);
  a03=(a23/a03);
  a36=(a36+a03);
  a03=(a65*a63);
  a35=(a66*a47);
  a03=(a03-a35);
  a35=(a37*a71);
  a03=(a03-a35);
  a36=(a36+a03);
  if (res[9]!=0) res[9][2]=a36;
  a36=(a38*a76);
  a03=(a77*a78);
  a36=(a36-a03);
  a03=(a85*a75);
  a36=(a36-a03);
  a36=(a36-a41);
  if (res[10]!=0) res[10][0]=a36;
  a36=(a50*a76);
  a41=(a57*a78);
  a36=(a36-a41);
  a41=(a59*a75);
  a36=(a36-a41);
  if (res[10]!=0) res[10][1]=a36;
  a36=(a66*a76);
  a41=(a65*a78);
  a36=(a36-a41);
  a41=(a37*a75);
  a36=(a36-a41);
  if (res[10]!=0) res[10][2]=a36;
  a36=(a77*a81);
  a41=(a38*a79);
  a36=(a36-a41);
  a41=(a85*a80);
  a36=(a36-a41);
  a43=(a43+a36);
  if (res[10]!=0) res[10][3]=a43;
  a43=(a57*a81);
  a36=(a50*a79);
  a43=(a43-a36);
  a36=(a59*a80);
  a43=(a43-a36);
  if (res[10]!=0) res[10][4]=a43;
  a43=(a65*a81);
  a36=(a66*a79);
  a43=(a43-a36);
  a36=(a37*a80);
  a43=(a43-a36);
  if (res[10]!=0) res[10][5]=a43;
  a43=(a77*a84);
  a36=(a38*a82);
  a43=(a43-a36);
  a36=(a85*a83);
  a43=(a43-a36);
  a01=(a01+a43);
  if (res[10]!=0) res[10][6]=a01;
  a01=(a57*a84);
  a43=(a50*a82);
  a01=(a01-a43);
  a43=(a59*a83);
  a01=(a01-a43);
  if (res[10]!=0) res[10][7]=a01;
  a01=(a65*a84);
  a43=(a66*a82);
  a01=(a01-a43);
  a43=(a37*a83);
  a01=(a01-a43);
  if (res[10]!=0) res[10][8]=a01;
  a01=(a38*a45);
  a43=(a77*a61);
  a01=(a01+a43);
  a43=(a85*a74);
  a01=(a01+a43);
  if (res[11]!=0) res[11][0]=a01;
  a01=(a50*a45);
  a43=(a57*a61);
  a01=(a01+a43);
  a43=(a59*a74);
  a01=(a01+a43);
  if (res[11]!=0) res[11][1]=a01;
  a45=(a66*a45);
  a61=(a65*a61);
  a45=(a45+a61);
  a74=(a37*a74);
  a45=(a45+a74);
  if (res[11]!=0) res[11][2]=a45;
  a45=(a34*a19);
  a74=(a67*a33);
  a45=(a45-a74);
  a74=(a86*a17);
  a45=(a45-a74);
  a45=(a45*a34);
  a19=(a27*a19);
  a74=(a67*a32);
  a19=(a19+a74);
  a74=(a86*a15);
  a19=(a19+a74);
  a19=(a19*a27);
  a45=(a45+a19);
  a32=(a27*a32);
  a33=(a34*a33);
  a32=(a32-a33);
  a29=(a67*a29);
  a32=(a32+a29);
  a29=(a86*a31);
  a32=(a32+a29);
  a32=(a32*a67);
  a45=(a45+a32);
  a27=(a27*a15);
  a34=(a34*a17);
  a27=(a27-a34);
  a67=(a67*a31);
  a27=(a27+a67);
  a30=(a86*a30);
  a27=(a27+a30);
  a27=(a27*a86);
  a45=(a45+a27);
  if (res[12]!=0) res[12][0]=a45;
  a45=(a26*a40);
  a45=(a45*a26);
  a40=(a69*a40);
  a40=(a40*a69);
  a45=(a45+a40);
  a16=(a53*a16);
  a16=(a16*a53);
  a45=(a45+a16);
  if (res[13]!=0) res[13][0]=a45;
  a45=(a63*a57);
  a16=(a47*a77);
  a45=(a45-a16);
  a16=(a71*a65);
  a45=(a45-a16);
  a45=(a45*a63);
  a16=(a63*a50);
  a53=(a47*a38);
  a16=(a16-a53);
  a53=(a71*a66);
  a16=(a16-a53);
  a16=(a16*a47);
  a45=(a45-a16);
  a16=(a63*a59);
  a53=(a47*a85);
  a16=(a16-a53);
  a53=(a71*a37);
  a16=(a16-a53);
  a16=(a16*a71);
  a45=(a45-a16);
  if (res[14]!=0) res[14][0]=a45;
  if (res[15]!=0) res[15][0]=a87;
  a04=(a00*a04);
  a87=(a04/a14);
  a58=(a48*a58);
  a45=(a52*a04);
  a58=(a58-a45);
  a45=(a58/a62);
  a06=(a64*a06);
  a04=(a68*a04);
  a06=(a06-a04);
  a58=(a05*a58);
  a06=(a06-a58);
  a06=(a06/a46);
  a58=(a05*a06);
  a45=(a45-a58);
  a58=(a52*a45);
  a87=(a87-a58);
  a58=(a68*a06);
  a87=(a87-a58);
  if (res[16]!=0) res[16][0]=a87;
  if (res[16]!=0) res[16][1]=a45;
  if (res[16]!=0) res[16][2]=a06;
  a39=(a00*a39);
  a58=(a39/a14);
  a56=(a48*a56);
  a04=(a52*a39);
  a56=(a56+a04);
  a04=(a56/a62);
  a55=(a64*a55);
  a39=(a68*a39);
  a55=(a55+a39);
  a56=(a05*a56);
  a55=(a55-a56);
  a55=(a55/a46);
  a56=(a05*a55);
  a04=(a04-a56);
  a56=(a52*a04);
  a58=(a58+a56);
  a56=(a68*a55);
  a58=(a58+a56);
  a56=(-a58);
  if (res[16]!=0) res[16][3]=a56;
  if (res[16]!=0) res[16][4]=a04;
  if (res[16]!=0) res[16][5]=a55;
  a00=(a00*a07);
  a14=(a00/a14);
  a48=(a48*a54);
  a54=(a52*a00);
  a48=(a48-a54);
  a54=(a48/a62);
  a64=(a64*a70);
  a00=(a68*a00);
  a64=(a64-a00);
  a48=(a05*a48);
  a64=(a64-a48);
  a64=(a64/a46);
  a05=(a05*a64);
  a54=(a54-a05);
  a52=(a52*a54);
  a14=(a14-a52);
  a68=(a68*a64);
  a14=(a14-a68);
  if (res[16]!=0) res[16][6]=a14;
  if (res[16]!=0) res[16][7]=a54;
  if (res[16]!=0) res[16][8]=a64;
  if (res[16]!=0) res[16][9]=a47;
  a68=(-a63);
  if (res[16]!=0) res[16][10]=a68;
  if (res[16]!=0) res[16][11]=a71;
  a68=(-a76);
  if (res[16]!=0) res[16][12]=a68;
  if (res[16]!=0) res[16][13]=a78;
  if (res[16]!=0) res[16][14]=a75;
  if (res[16]!=0) res[16][15]=a79;
  a68=(-a81);
  if (res[16]!=0) res[16][16]=a68;
  if (res[16]!=0) res[16][17]=a80;
  if (res[16]!=0) res[16][18]=a82;
  a68=(-a84);
  if (res[16]!=0) res[16][19]=a68;
  if (res[16]!=0) res[16][20]=a83;
  a68=(a25*a87);
  a52=(a02*a45);
  a68=(a68-a52);
  a52=(a22*a06);
  a68=(a68-a52);
  a68=(a44-a68);
  if (res[17]!=0) res[17][0]=a68;
  a68=(a08*a45);
  a52=(a28*a87);
  a68=(a68-a52);
  a52=(a10*a06);
  a68=(a68+a52);
  a68=(-a68);
  if (res[17]!=0) res[17][1]=a68;
  a68=(a21*a87);
  a45=(a49*a45);
  a68=(a68+a45);
  a45=(a20*a06);
  a68=(a68+a45);
  a68=(-a68);
  if (res[17]!=0) res[17][2]=a68;
  a68=(a13*a87);
  a06=(a23*a06);
  a68=(a68+a06);
  a68=(-a68);
  if (res[17]!=0) res[17][3]=a68;
  a68=(a12*a87);
  if (res[17]!=0) res[17][4]=a68;
  a68=(a18*a87);
  a68=(-a68);
  if (res[17]!=0) res[17][5]=a68;
  a87=(a09*a87);
  a87=(-a87);
  if (res[17]!=0) res[17][6]=a87;
  a87=(a25*a58);
  a68=(a02*a04);
  a87=(a87+a68);
  a68=(a22*a55);
  a87=(a87+a68);
  if (res[17]!=0) res[17][7]=a87;
  a87=(a28*a58);
  a68=(a08*a04);
  a87=(a87+a68);
  a68=(a10*a55);
  a87=(a87+a68);
  a87=(a44-a87);
  if (res[17]!=0) res[17][8]=a87;
  a04=(a49*a04);
  a87=(a21*a58);
  a04=(a04-a87);
  a87=(a20*a55);
  a04=(a04+a87);
  a04=(-a04);
  if (res[17]!=0) res[17][9]=a04;
  a55=(a23*a55);
  a04=(a13*a58);
  a55=(a55-a04);
  a55=(-a55);
  if (res[17]!=0) res[17][10]=a55;
  a55=(a12*a58);
  a55=(-a55);
  if (res[17]!=0) res[17][11]=a55;
  a55=(a18*a58);
  if (res[17]!=0) res[17][12]=a55;
  a58=(a09*a58);
  if (res[17]!=0) res[17][13]=a58;
  a58=(a25*a14);
  a55=(a02*a54);
  a58=(a58-a55);
  a55=(a22*a64);
  a58=(a58-a55);
  a58=(-a58);
  if (res[17]!=0) res[17][14]=a58;
  a58=(a08*a54);
  a55=(a28*a14);
  a58=(a58-a55);
  a55=(a10*a64);
  a58=(a58+a55);
  a58=(-a58);
  if (res[17]!=0) res[17][15]=a58;
  a58=(a21*a14);
  a54=(a49*a54);
  a58=(a58+a54);
  a54=(a20*a64);
  a58=(a58+a54);
  a58=(a44-a58);
  if (res[17]!=0) res[17][16]=a58;
  a58=(a13*a14);
  a64=(a23*a64);
  a58=(a58+a64);
  a58=(-a58);
  if (res[17]!=0) res[17][17]=a58;
  a58=(a12*a14);
  if (res[17]!=0) res[17][18]=a58;
  a58=(a18*a14);
  a58=(-a58);
  if (res[17]!=0) res[17][19]=a58;
  a14=(a09*a14);
  a14=(-a14);
  if (res[17]!=0) res[17][20]=a14;
  a14=(a25*a47);
  a58=(a02*a63);
  a14=(a14+a58);
  a58=(a22*a71);
  a14=(a14-a58);
  a14=(-a14);
  if (res[17]!=0) res[17][21]=a14;
  a14=(a10*a71);
  a58=(a28*a47);
  a64=(a08*a63);
  a58=(a58+a64);
  a14=(a14-a58);
  a14=(-a14);
  if (res[17]!=0) res[17][22]=a14;
  a14=(a21*a47);
  a63=(a49*a63);
  a14=(a14-a63);
  a63=(a20*a71);
  a14=(a14+a63);
  a14=(-a14);
  if (res[17]!=0) res[17][23]=a14;
  a14=(a13*a47);
  a71=(a23*a71);
  a14=(a14+a71);
  a14=(a44-a14);
  if (res[17]!=0) res[17][24]=a14;
  a14=(a12*a47);
  if (res[17]!=0) res[17][25]=a14;
  a14=(a18*a47);
  a14=(-a14);
  if (res[17]!=0) res[17][26]=a14;
  a47=(a09*a47);
  a47=(-a47);
  if (res[17]!=0) res[17][27]=a47;
  a47=(a25*a76);
  a14=(a02*a78);
  a47=(a47+a14);
  a14=(a22*a75);
  a47=(a47+a14);
  if (res[17]!=0) res[17][28]=a47;
  a47=(a28*a76);
  a14=(a08*a78);
  a47=(a47+a14);
  a14=(a10*a75);
  a47=(a47+a14);
  a47=(-a47);
  if (res[17]!=0) res[17][29]=a47;
  a78=(a49*a78);
  a47=(a21*a76);
  a78=(a78-a47);
  a47=(a20*a75);
  a78=(a78+a47);
  a78=(-a78);
  if (res[17]!=0) res[17][30]=a78;
  a75=(a23*a75);
  a78=(a13*a76);
  a75=(a75-a78);
  a75=(-a75);
  if (res[17]!=0) res[17][31]=a75;
  a75=(a12*a76);
  a75=(a44-a75);
  if (res[17]!=0) res[17][32]=a75;
  a75=(a18*a76);
  if (res[17]!=0) res[17][33]=a75;
  a76=(a09*a76);
  if (res[17]!=0) res[17][34]=a76;
  a76=(a25*a79);
  a75=(a02*a81);
  a76=(a76+a75);
  a75=(a22*a80);
  a76=(a76-a75);
  a76=(-a76);
  if (res[17]!=0) res[17][35]=a76;
  a76=(a10*a80);
  a75=(a28*a79);
  a78=(a08*a81);
  a75=(a75+a78);
  a76=(a76-a75);
  a76=(-a76);
  if (res[17]!=0) res[17][36]=a76;
  a76=(a21*a79);
  a81=(a49*a81);
  a76=(a76-a81);
  a81=(a20*a80);
  a76=(a76+a81);
  a76=(-a76);
  if (res[17]!=0) res[17][37]=a76;
  a76=(a13*a79);
  a80=(a23*a80);
  a76=(a76+a80);
  a76=(-a76);
  if (res[17]!=0) res[17][38]=a76;
  a76=(a12*a79);
  if (res[17]!=0) res[17][39]=a76;
  a76=(a18*a79);
  a76=(a44-a76);
  if (res[17]!=0) res[17][40]=a76;
  a79=(a09*a79);
  a79=(-a79);
  if (res[17]!=0) res[17][41]=a79;
  a25=(a25*a82);
  a02=(a02*a84);
  a25=(a25+a02);
  a22=(a22*a83);
  a25=(a25-a22);
  a25=(-a25);
  if (res[17]!=0) res[17][42]=a25;
  a10=(a10*a83);
  a28=(a28*a82);
  a08=(a08*a84);
  a28=(a28+a08);
  a10=(a10-a28);
  a10=(-a10);
  if (res[17]!=0) res[17][43]=a10;
  a21=(a21*a82);
  a49=(a49*a84);
  a21=(a21-a49);
  a20=(a20*a83);
  a21=(a21+a20);
  a21=(-a21);
  if (res[17]!=0) res[17][44]=a21;
  a13=(a13*a82);
  a23=(a23*a83);
  a13=(a13+a23);
  a13=(-a13);
  if (res[17]!=0) res[17][45]=a13;
  a12=(a12*a82);
  if (res[17]!=0) res[17][46]=a12;
  a18=(a18*a82);
  a18=(-a18);
  if (res[17]!=0) res[17][47]=a18;
  a09=(a09*a82);
  a09=(a44-a09);
  if (res[17]!=0) res[17][48]=a09;
  if (res[18]!=0) res[18][0]=a38;
  if (res[18]!=0) res[18][1]=a50;
  if (res[18]!=0) res[18][2]=a66;
  if (res[18]!=0) res[18][3]=a77;
  if (res[18]!=0) res[18][4]=a57;
  if (res[18]!=0) res[18][5]=a65;
  if (res[18]!=0) res[18][6]=a85;
  if (res[18]!=0) res[18][7]=a59;
  if (res[18]!=0) res[18][8]=a37;
  a62=(a62/a60);
  a44=casadi_fmin(a44,a62);
  a46=(a46/a73);
  a44=casadi_fmin(a44,a46);
  if (res[19]!=0) res[19][0]=a44;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_interaction_maps_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_interaction_maps_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_interaction_maps_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_interaction_maps_n_in(void) { return 12;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_interaction_maps_n_out(void) { return 20;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_interaction_maps_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_interaction_maps_name_in(casadi_int i) {
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
    case 10: return "lam_fixed";
    case 11: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_interaction_maps_name_out(casadi_int i) {
  switch (i) {
    case 0: return "lam_from_tau";
    case 1: return "lam_from_f_obj";
    case 2: return "lam_offset";
    case 3: return "qdd_from_tau";
    case 4: return "qdd_from_f_obj";
    case 5: return "qdd_offset";
    case 6: return "a_obj_from_tau";
    case 7: return "a_obj_from_f_obj";
    case 8: return "a_obj_offset";
    case 9: return "w_from_tau";
    case 10: return "w_from_f_obj";
    case 11: return "w_offset";
    case 12: return "xi_tau";
    case 13: return "omega_tau";
    case 14: return "lambda_form_tau";
    case 15: return "input_metric";
    case 16: return "projector_constrained";
    case 17: return "projector_orthogonal";
    case 18: return "delassus";
    case 19: return "pivot_ratio";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_interaction_maps_sparsity_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_interaction_maps_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s5;
    case 2: return casadi_s4;
    case 3: return casadi_s0;
    case 4: return casadi_s6;
    case 5: return casadi_s0;
    case 6: return casadi_s4;
    case 7: return casadi_s5;
    case 8: return casadi_s4;
    case 9: return casadi_s4;
    case 10: return casadi_s5;
    case 11: return casadi_s4;
    case 12: return casadi_s3;
    case 13: return casadi_s3;
    case 14: return casadi_s3;
    case 15: return casadi_s3;
    case 16: return casadi_s7;
    case 17: return casadi_s8;
    case 18: return casadi_s5;
    case 19: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12;
  if (sz_res) *sz_res = 20;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_interaction_maps_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 20*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_interaction_maps(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[12];
  casadi_real* r[20];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 89);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 12; ++k) a[k] = 0;
  for (k = 0; k < 20; ++k) r[k] = 0;
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
    r[0] = res[0] + i * 3;
    r[1] = res[1] + i * 9;
    r[2] = res[2] + i * 3;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 12;
    r[5] = res[5] + i * 4;
    r[6] = res[6] + i * 3;
    r[7] = res[7] + i * 9;
    r[8] = res[8] + i * 3;
    r[9] = res[9] + i * 3;
    r[10] = res[10] + i * 9;
    r[11] = res[11] + i * 3;
    r[12] = res[12] + i * 1;
    r[13] = res[13] + i * 1;
    r[14] = res[14] + i * 1;
    r[15] = res[15] + i * 1;
    r[16] = res[16] + i * 21;
    r[17] = res[17] + i * 49;
    r[18] = res[18] + i * 9;
    r[19] = res[19] + i * 1;
    if (snakecg_na1_interaction_maps(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
