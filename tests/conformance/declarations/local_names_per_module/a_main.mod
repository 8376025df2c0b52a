MODULE a_main
  ! Tests: LOCAL data and LOCAL routines are private to their module, so two
  ! modules may each declare a LOCAL x and a LOCAL show without conflict;
  ! each module's code sees its own.
  LOCAL VAR num x := 1;
  LOCAL PROC show()
    TPWrite "a sees " \Num:=x;
  ENDPROC
  PROC main()
    show;
    ShowB;
  ENDPROC
ENDMODULE
