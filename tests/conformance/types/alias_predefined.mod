MODULE alias_predefined
  ! Tests: predefined aliases of num (errnum, intnum, dionum, byte) hold
  ! num values and mix with num.
  PROC main()
    VAR errnum e := 5;
    VAR byte b := 200;
    VAR dionum d := 1;
    VAR num n;
    n := e + b + d;
    TPWrite "n=" \Num:=n;
  ENDPROC
ENDMODULE
