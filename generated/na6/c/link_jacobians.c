/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_jacobians() of
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
  #define CASADI_PREFIX(ID) snakecg_na6_link_jacobians_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na6_link_jacobians_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {21, 9, 1};

/* snakecg_na6_link_jacobians:(q[9],K[71])->(J[21x9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39;
  a00=1.;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  if (res[0]!=0) res[0][2]=a01;
  if (res[0]!=0) res[0][3]=a00;
  if (res[0]!=0) res[0][4]=a01;
  if (res[0]!=0) res[0][5]=a01;
  if (res[0]!=0) res[0][6]=a00;
  if (res[0]!=0) res[0][7]=a01;
  if (res[0]!=0) res[0][8]=a01;
  if (res[0]!=0) res[0][9]=a00;
  if (res[0]!=0) res[0][10]=a01;
  if (res[0]!=0) res[0][11]=a01;
  if (res[0]!=0) res[0][12]=a00;
  if (res[0]!=0) res[0][13]=a01;
  if (res[0]!=0) res[0][14]=a01;
  if (res[0]!=0) res[0][15]=a00;
  if (res[0]!=0) res[0][16]=a01;
  if (res[0]!=0) res[0][17]=a01;
  if (res[0]!=0) res[0][18]=a00;
  if (res[0]!=0) res[0][19]=a01;
  if (res[0]!=0) res[0][20]=a01;
  if (res[0]!=0) res[0][21]=a01;
  if (res[0]!=0) res[0][22]=a00;
  if (res[0]!=0) res[0][23]=a01;
  if (res[0]!=0) res[0][24]=a01;
  if (res[0]!=0) res[0][25]=a00;
  if (res[0]!=0) res[0][26]=a01;
  if (res[0]!=0) res[0][27]=a01;
  if (res[0]!=0) res[0][28]=a00;
  if (res[0]!=0) res[0][29]=a01;
  if (res[0]!=0) res[0][30]=a01;
  if (res[0]!=0) res[0][31]=a00;
  if (res[0]!=0) res[0][32]=a01;
  if (res[0]!=0) res[0][33]=a01;
  if (res[0]!=0) res[0][34]=a00;
  if (res[0]!=0) res[0][35]=a01;
  if (res[0]!=0) res[0][36]=a01;
  if (res[0]!=0) res[0][37]=a00;
  if (res[0]!=0) res[0][38]=a01;
  if (res[0]!=0) res[0][39]=a01;
  if (res[0]!=0) res[0][40]=a00;
  if (res[0]!=0) res[0][41]=a01;
  if (res[0]!=0) res[0][42]=a01;
  if (res[0]!=0) res[0][43]=a01;
  if (res[0]!=0) res[0][44]=a00;
  a02=arg[0]? arg[0][1] : 0;
  a03=arg[1]? arg[1][7] : 0;
  a04=arg[1]? arg[1][21] : 0;
  a03=(a03-a04);
  a04=arg[0]? arg[0][2] : 0;
  a05=sin(a04);
  a06=(a03*a05);
  a06=(a02+a06);
  a04=cos(a04);
  a07=arg[0]? arg[0][3] : 0;
  a08=sin(a07);
  a09=(a04*a08);
  a07=cos(a07);
  a10=(a07*a05);
  a09=(a09+a10);
  a10=arg[1]? arg[1][22] : 0;
  a11=(a09*a10);
  a12=(a06+a11);
  a13=(a02-a12);
  if (res[0]!=0) res[0][45]=a13;
  a13=arg[0]? arg[0][0] : 0;
  a03=(a04*a03);
  a03=(a13+a03);
  a04=(a04*a07);
  a05=(a05*a08);
  a04=(a04-a05);
  a05=(a04*a10);
  a08=(a03+a05);
  a07=(a08-a13);
  if (res[0]!=0) res[0][46]=a07;
  if (res[0]!=0) res[0][47]=a00;
  a07=arg[1]? arg[1][8] : 0;
  a07=(a07-a10);
  a10=(a07*a09);
  a12=(a12+a10);
  a10=arg[0]? arg[0][4] : 0;
  a14=sin(a10);
  a15=(a04*a14);
  a10=cos(a10);
  a16=(a10*a09);
  a15=(a15+a16);
  a16=arg[1]? arg[1][23] : 0;
  a17=(a15*a16);
  a18=(a12+a17);
  a19=(a02-a18);
  if (res[0]!=0) res[0][48]=a19;
  a07=(a04*a07);
  a08=(a08+a07);
  a04=(a04*a10);
  a09=(a09*a14);
  a04=(a04-a09);
  a09=(a04*a16);
  a14=(a08+a09);
  a10=(a14-a13);
  if (res[0]!=0) res[0][49]=a10;
  if (res[0]!=0) res[0][50]=a00;
  a10=arg[1]? arg[1][9] : 0;
  a10=(a10-a16);
  a16=(a10*a15);
  a16=(a18+a16);
  a07=arg[0]? arg[0][5] : 0;
  a19=sin(a07);
  a20=(a04*a19);
  a07=cos(a07);
  a21=(a07*a15);
  a20=(a20+a21);
  a21=arg[1]? arg[1][24] : 0;
  a22=(a20*a21);
  a23=(a16+a22);
  a24=(a02-a23);
  if (res[0]!=0) res[0][51]=a24;
  a10=(a04*a10);
  a10=(a14+a10);
  a04=(a04*a07);
  a15=(a15*a19);
  a04=(a04-a15);
  a15=(a04*a21);
  a19=(a10+a15);
  a07=(a19-a13);
  if (res[0]!=0) res[0][52]=a07;
  if (res[0]!=0) res[0][53]=a00;
  a07=arg[1]? arg[1][10] : 0;
  a07=(a07-a21);
  a21=(a07*a20);
  a21=(a23+a21);
  a24=arg[0]? arg[0][6] : 0;
  a25=sin(a24);
  a26=(a04*a25);
  a24=cos(a24);
  a27=(a24*a20);
  a26=(a26+a27);
  a27=arg[1]? arg[1][25] : 0;
  a28=(a26*a27);
  a29=(a21+a28);
  a30=(a02-a29);
  if (res[0]!=0) res[0][54]=a30;
  a07=(a04*a07);
  a07=(a19+a07);
  a04=(a04*a24);
  a20=(a20*a25);
  a04=(a04-a20);
  a20=(a04*a27);
  a25=(a07+a20);
  a24=(a25-a13);
  if (res[0]!=0) res[0][55]=a24;
  if (res[0]!=0) res[0][56]=a00;
  a24=arg[1]? arg[1][11] : 0;
  a24=(a24-a27);
  a27=(a24*a26);
  a27=(a29+a27);
  a30=arg[0]? arg[0][7] : 0;
  a31=sin(a30);
  a32=(a04*a31);
  a30=cos(a30);
  a33=(a30*a26);
  a32=(a32+a33);
  a33=arg[1]? arg[1][26] : 0;
  a34=(a32*a33);
  a35=(a27+a34);
  a36=(a02-a35);
  if (res[0]!=0) res[0][57]=a36;
  a24=(a04*a24);
  a24=(a25+a24);
  a04=(a04*a30);
  a26=(a26*a31);
  a04=(a04-a26);
  a26=(a04*a33);
  a31=(a24+a26);
  a30=(a31-a13);
  if (res[0]!=0) res[0][58]=a30;
  if (res[0]!=0) res[0][59]=a00;
  a30=arg[1]? arg[1][12] : 0;
  a30=(a30-a33);
  a33=(a30*a32);
  a33=(a35+a33);
  a36=arg[0]? arg[0][8] : 0;
  a37=sin(a36);
  a38=(a04*a37);
  a36=cos(a36);
  a39=(a36*a32);
  a38=(a38+a39);
  a39=arg[1]? arg[1][27] : 0;
  a38=(a38*a39);
  a33=(a33+a38);
  a02=(a02-a33);
  if (res[0]!=0) res[0][60]=a02;
  a30=(a04*a30);
  a30=(a31+a30);
  a04=(a04*a36);
  a32=(a32*a37);
  a04=(a04-a32);
  a04=(a04*a39);
  a30=(a30+a04);
  a13=(a30-a13);
  if (res[0]!=0) res[0][61]=a13;
  if (res[0]!=0) res[0][62]=a00;
  if (res[0]!=0) res[0][63]=a01;
  if (res[0]!=0) res[0][64]=a01;
  if (res[0]!=0) res[0][65]=a01;
  a11=(-a11);
  if (res[0]!=0) res[0][66]=a11;
  if (res[0]!=0) res[0][67]=a05;
  if (res[0]!=0) res[0][68]=a00;
  a18=(a06-a18);
  if (res[0]!=0) res[0][69]=a18;
  a14=(a14-a03);
  if (res[0]!=0) res[0][70]=a14;
  if (res[0]!=0) res[0][71]=a00;
  a14=(a06-a23);
  if (res[0]!=0) res[0][72]=a14;
  a14=(a19-a03);
  if (res[0]!=0) res[0][73]=a14;
  if (res[0]!=0) res[0][74]=a00;
  a14=(a06-a29);
  if (res[0]!=0) res[0][75]=a14;
  a14=(a25-a03);
  if (res[0]!=0) res[0][76]=a14;
  if (res[0]!=0) res[0][77]=a00;
  a14=(a06-a35);
  if (res[0]!=0) res[0][78]=a14;
  a14=(a31-a03);
  if (res[0]!=0) res[0][79]=a14;
  if (res[0]!=0) res[0][80]=a00;
  a06=(a06-a33);
  if (res[0]!=0) res[0][81]=a06;
  a03=(a30-a03);
  if (res[0]!=0) res[0][82]=a03;
  if (res[0]!=0) res[0][83]=a00;
  if (res[0]!=0) res[0][84]=a01;
  if (res[0]!=0) res[0][85]=a01;
  if (res[0]!=0) res[0][86]=a01;
  if (res[0]!=0) res[0][87]=a01;
  if (res[0]!=0) res[0][88]=a01;
  if (res[0]!=0) res[0][89]=a01;
  a17=(-a17);
  if (res[0]!=0) res[0][90]=a17;
  if (res[0]!=0) res[0][91]=a09;
  if (res[0]!=0) res[0][92]=a00;
  a23=(a12-a23);
  if (res[0]!=0) res[0][93]=a23;
  a19=(a19-a08);
  if (res[0]!=0) res[0][94]=a19;
  if (res[0]!=0) res[0][95]=a00;
  a19=(a12-a29);
  if (res[0]!=0) res[0][96]=a19;
  a19=(a25-a08);
  if (res[0]!=0) res[0][97]=a19;
  if (res[0]!=0) res[0][98]=a00;
  a19=(a12-a35);
  if (res[0]!=0) res[0][99]=a19;
  a19=(a31-a08);
  if (res[0]!=0) res[0][100]=a19;
  if (res[0]!=0) res[0][101]=a00;
  a12=(a12-a33);
  if (res[0]!=0) res[0][102]=a12;
  a08=(a30-a08);
  if (res[0]!=0) res[0][103]=a08;
  if (res[0]!=0) res[0][104]=a00;
  if (res[0]!=0) res[0][105]=a01;
  if (res[0]!=0) res[0][106]=a01;
  if (res[0]!=0) res[0][107]=a01;
  if (res[0]!=0) res[0][108]=a01;
  if (res[0]!=0) res[0][109]=a01;
  if (res[0]!=0) res[0][110]=a01;
  if (res[0]!=0) res[0][111]=a01;
  if (res[0]!=0) res[0][112]=a01;
  if (res[0]!=0) res[0][113]=a01;
  a22=(-a22);
  if (res[0]!=0) res[0][114]=a22;
  if (res[0]!=0) res[0][115]=a15;
  if (res[0]!=0) res[0][116]=a00;
  a29=(a16-a29);
  if (res[0]!=0) res[0][117]=a29;
  a25=(a25-a10);
  if (res[0]!=0) res[0][118]=a25;
  if (res[0]!=0) res[0][119]=a00;
  a25=(a16-a35);
  if (res[0]!=0) res[0][120]=a25;
  a25=(a31-a10);
  if (res[0]!=0) res[0][121]=a25;
  if (res[0]!=0) res[0][122]=a00;
  a16=(a16-a33);
  if (res[0]!=0) res[0][123]=a16;
  a10=(a30-a10);
  if (res[0]!=0) res[0][124]=a10;
  if (res[0]!=0) res[0][125]=a00;
  if (res[0]!=0) res[0][126]=a01;
  if (res[0]!=0) res[0][127]=a01;
  if (res[0]!=0) res[0][128]=a01;
  if (res[0]!=0) res[0][129]=a01;
  if (res[0]!=0) res[0][130]=a01;
  if (res[0]!=0) res[0][131]=a01;
  if (res[0]!=0) res[0][132]=a01;
  if (res[0]!=0) res[0][133]=a01;
  if (res[0]!=0) res[0][134]=a01;
  if (res[0]!=0) res[0][135]=a01;
  if (res[0]!=0) res[0][136]=a01;
  if (res[0]!=0) res[0][137]=a01;
  a28=(-a28);
  if (res[0]!=0) res[0][138]=a28;
  if (res[0]!=0) res[0][139]=a20;
  if (res[0]!=0) res[0][140]=a00;
  a35=(a21-a35);
  if (res[0]!=0) res[0][141]=a35;
  a31=(a31-a07);
  if (res[0]!=0) res[0][142]=a31;
  if (res[0]!=0) res[0][143]=a00;
  a21=(a21-a33);
  if (res[0]!=0) res[0][144]=a21;
  a07=(a30-a07);
  if (res[0]!=0) res[0][145]=a07;
  if (res[0]!=0) res[0][146]=a00;
  if (res[0]!=0) res[0][147]=a01;
  if (res[0]!=0) res[0][148]=a01;
  if (res[0]!=0) res[0][149]=a01;
  if (res[0]!=0) res[0][150]=a01;
  if (res[0]!=0) res[0][151]=a01;
  if (res[0]!=0) res[0][152]=a01;
  if (res[0]!=0) res[0][153]=a01;
  if (res[0]!=0) res[0][154]=a01;
  if (res[0]!=0) res[0][155]=a01;
  if (res[0]!=0) res[0][156]=a01;
  if (res[0]!=0) res[0][157]=a01;
  if (res[0]!=0) res[0][158]=a01;
  if (res[0]!=0) res[0][159]=a01;
  if (res[0]!=0) res[0][160]=a01;
  if (res[0]!=0) res[0][161]=a01;
  a34=(-a34);
  if (res[0]!=0) res[0][162]=a34;
  if (res[0]!=0) res[0][163]=a26;
  if (res[0]!=0) res[0][164]=a00;
  a27=(a27-a33);
  if (res[0]!=0) res[0][165]=a27;
  a30=(a30-a24);
  if (res[0]!=0) res[0][166]=a30;
  if (res[0]!=0) res[0][167]=a00;
  if (res[0]!=0) res[0][168]=a01;
  if (res[0]!=0) res[0][169]=a01;
  if (res[0]!=0) res[0][170]=a01;
  if (res[0]!=0) res[0][171]=a01;
  if (res[0]!=0) res[0][172]=a01;
  if (res[0]!=0) res[0][173]=a01;
  if (res[0]!=0) res[0][174]=a01;
  if (res[0]!=0) res[0][175]=a01;
  if (res[0]!=0) res[0][176]=a01;
  if (res[0]!=0) res[0][177]=a01;
  if (res[0]!=0) res[0][178]=a01;
  if (res[0]!=0) res[0][179]=a01;
  if (res[0]!=0) res[0][180]=a01;
  if (res[0]!=0) res[0][181]=a01;
  if (res[0]!=0) res[0][182]=a01;
  if (res[0]!=0) res[0][183]=a01;
  if (res[0]!=0) res[0][184]=a01;
  if (res[0]!=0) res[0][185]=a01;
  a38=(-a38);
  if (res[0]!=0) res[0][186]=a38;
  if (res[0]!=0) res[0][187]=a04;
  if (res[0]!=0) res[0][188]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_jacobians_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_jacobians_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_jacobians_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_link_jacobians_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_link_jacobians_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na6_link_jacobians_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_link_jacobians_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_link_jacobians_name_out(casadi_int i) {
  switch (i) {
    case 0: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_link_jacobians_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_link_jacobians_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na6_batch_link_jacobians(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 41);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 189;
    if (snakecg_na6_link_jacobians(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
