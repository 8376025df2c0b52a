MODULE inout_parameter
  ! Tests: an INOUT parameter is passed by reference and accepts both a
  ! variable and a persistent.
  PERS num counter := 10;
  PROC twice(INOUT num v)
    v := v * 2;
  ENDPROC
  PROC main()
    VAR num n := 3;
    twice n;
    twice counter;
    TPWrite "n=" \Num:=n;
    TPWrite "counter=" \Num:=counter;
  ENDPROC
ENDMODULE
