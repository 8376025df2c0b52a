MODULE MainModule
  ! Tests: Decr subtracts 1 from a num variable (also past zero), an array element and a dnum.
  PROC main()
    VAR num n := 1;
    VAR num arr{2} := [10, 20];
    VAR dnum d := 0;
    Decr n;
    TPWrite "n=" \Num:=n;
    Decr n;
    TPWrite "n=" \Num:=n;
    Decr arr{2};
    TPWrite "arr2=" \Num:=arr{2};
    Decr d;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
