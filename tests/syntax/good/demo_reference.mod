%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%
! The worked example of the language reference (section 2.0), lightly varied.
MODULE Demo(NOSTEPIN)
  RECORD part
    num id;
    string name;
    pos where;
  ENDRECORD
  ALIAS num level;
  CONST num N := 3;
  LOCAL VAR num cnt{N} := [0, 0, 0];
  PERS part last := [0, "", [0, 0, 0]];
  TASK PERS bool busy := FALSE;
  VAR intnum irTick;
  CONST errnum ERR_MINE := 10;

  PROC main()
    VAR num i;
    VAR string s := "say ""hi"" \\ bell\07";
    IDelete irTick;
    CONNECT irTick WITH tick;
    ITimer 1, irTick;
    FOR k FROM 1 TO N DO
      cnt{k} := k * 2;
    ENDFOR
    IF cnt{2} > 3 i := Area(2, 3 \Scale:=2);    ! compact IF
    TEST i
      CASE 6, 12: TPWrite "area "\Num:=i;
      DEFAULT: Stop;
    ENDTEST
    WHILE (NOT busy) AND i < 100 DO
      Incr i;
    ENDWHILE
    %"Step" + NumToStr(1, 0)%;
    RAISE ERR_MINE;
  ERROR
    IF ERRNO = ERR_MINE THEN
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC

  FUNC num Area(num w, num h \num Scale | switch Half)
    VAR num a;
    a := w * h;
    IF Present(Scale) a := a * Scale;
    IF Present(Half) a := a / 2;
    RETURN a;
  ENDFUNC

  PROC Step1()
    last.where.x := last.where.x + 1;
  UNDO
    busy := FALSE;
  ENDPROC

  TRAP tick
    busy := NOT busy;
  ENDTRAP
ENDMODULE
