MODULE a_main
  ! Tests: within a module, a LOCAL data object hides a global one of the
  ! same name declared in another module; the other module still sees its
  ! global.
  LOCAL VAR num g := 1;
  PROC main()
    g := g + 10;
    TPWrite "a: g=" \Num:=g;
    ShowG;
  ENDPROC
ENDMODULE
