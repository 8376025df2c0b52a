MODULE MainModule
  ! Tests: GetDataVal and SetDataVal reach data by its name at run time; an unknown name
  ! raises ERR_SYM_ACCESS and data of another type ERR_SYMBOL_TYPE; ErrRaise raises the
  ! error number booked in the errnum data it names.
  PERS num nStation1 := 11;
  PERS num nStation2 := 22;
  PERS string sLabel := "A";
  VAR errnum ERR_GRIPPER := -1;
  VAR num nValue;

  PROC main()
    FOR i FROM 1 TO 2 DO
      GetDataVal "nStation" + NumToStr(i, 0), nValue;
      TPWrite "station " \Num:=nValue;
    ENDFOR
    SetDataVal "nStation2", 99;
    TPWrite "after set " \Num:=nStation2;
    ReadMissing;
    ReadWrongType;
    BookErrNo ERR_GRIPPER;
    CheckGripper;
  ENDPROC

  PROC ReadMissing()
    GetDataVal "nStation3", nValue;
  ERROR
    IF ERRNO = ERR_SYM_ACCESS TPWrite "no nStation3";
    RETURN;
  ENDPROC

  PROC ReadWrongType()
    GetDataVal "sLabel", nValue;
  ERROR
    IF ERRNO = ERR_SYMBOL_TYPE TPWrite "sLabel is not a num";
    RETURN;
  ENDPROC

  PROC CheckGripper()
    ErrRaise "ERR_GRIPPER", 7001, "Gripper", ERRSTR_TASK, "Gripper did not close",
      ERRSTR_CONTEXT, ERRSTR_EMPTY;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_GRIPPER TPWrite "gripper error raised";
    RETURN;
  ENDPROC
ENDMODULE
