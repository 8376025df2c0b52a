MODULE MainModule
  ! Tests: NumToDnum widens a num to dnum; further arithmetic is done in double precision
  ! (8388608 + 1 is exact in dnum).
  PROC main()
    VAR num n := 8388608;
    VAR dnum one := 1;
    VAR dnum d;
    d := NumToDnum(n) + one;
    TPWrite "d=" \Dnum:=d;
    TPWrite "neg=" \Dnum:=NumToDnum(-12.5);
  ENDPROC
ENDMODULE
