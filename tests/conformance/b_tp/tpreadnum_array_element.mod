MODULE MainModule
  ! Tests: TPReadNum can store the answer into an array element and a record component.
  PROC main()
    VAR num values{2};
    VAR pos p;
    TPReadNum values{2}, "Element?";
    TPReadNum p.z, "Height?";
    TPWrite "values2=" \Num:=values{2};
    TPWrite "p=" \Pos:=p;
  ENDPROC
ENDMODULE
