MODULE conditional_switch_argument
  ! Tests: a switch can be passed on conditionally (\Fast?Fast) through two
  ! levels of calls.
  PROC leaf(\switch Fast)
    TPWrite "fast " \Bool:=Present(Fast);
  ENDPROC
  PROC middle(\switch Fast)
    leaf \Fast?Fast;
  ENDPROC
  PROC main()
    middle \Fast;
    middle;
  ENDPROC
ENDMODULE
