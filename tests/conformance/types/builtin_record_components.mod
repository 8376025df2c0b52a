MODULE builtin_record_components
  ! Tests: installed record types (robtarget, tooldata) have the documented
  ! components: robtarget.trans/rot/robconf/extax, tooldata.tload.mass.
  VAR robtarget p := [[10, 20, 30], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    TPWrite "trans=" \Pos:=p.trans;
    TPWrite "rot=" \Orient:=p.rot;
    TPWrite "x=" \Num:=p.trans.x;
    p.robconf.cf1 := 1;
    TPWrite "cf1=" \Num:=p.robconf.cf1;
    TPWrite "robhold " \Bool:=tool0.robhold;
  ENDPROC
ENDMODULE
