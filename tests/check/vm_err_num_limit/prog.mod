MODULE VmErrNumLimit
    ! A num beyond the float32 range (about 3.4E38) raises ERR_NUM_LIMIT;
    ! a dnum goes on to about 1.8E308.
    VAR num x := 1;
    VAR dnum wide := 1;
    VAR num times := 0;
    VAR bool grow := FALSE;

    PROC main()
        WHILE TRUE DO
            grow := DInput(di_grow) = 1;
            IF grow THEN
                wide := wide * 1E30;
                x := x * 1E30;
                times := times + 1;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
