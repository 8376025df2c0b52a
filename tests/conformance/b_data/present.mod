MODULE MainModule
  ! Tests: Present is TRUE exactly when the optional parameter or switch was given.
  PROC main()
    Show;
    Show \Scale:=3;
    Show \Verbose;
    Show \Scale:=2 \Verbose;
  ENDPROC

  PROC Show(\num Scale, \switch Verbose)
    TPWrite "scale " \Bool:=Present(Scale);
    TPWrite "verbose " \Bool:=Present(Verbose);
  ENDPROC
ENDMODULE
