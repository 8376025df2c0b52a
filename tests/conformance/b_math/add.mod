MODULE MainModule
  ! Tests: Add adds a (possibly negative) value to a num variable, array element or record component.
  PROC main()
    VAR num reg1 := 10;
    VAR num reg2 := 4;
    VAR num arr{2} := [5, 6];
    VAR pos p := [1, 2, 3];
    Add reg1, 3;
    TPWrite "reg1=" \Num:=reg1;
    Add reg1, -reg2;
    TPWrite "reg1=" \Num:=reg1;
    Add arr{2}, 10;
    TPWrite "arr2=" \Num:=arr{2};
    Add p.z, 0.5;
    TPWrite "pz=" \Num:=p.z;
  ENDPROC
ENDMODULE
