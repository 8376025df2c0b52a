MODULE ConfigLookup
    ! Reads calibration values from the controller's configuration, in the style of
    ! service programs that must run on several robot variants: an instance that is
    ! not configured raises ERR_CFG_NOTFND, and the handler gives a marker value.
    CONST num NOT_CONFIGURED := 9E+09;
    VAR num axisOffset{3};
    VAR num missing := 0;

    PROC main()
        FOR i FROM 1 TO 3 DO
            axisOffset{i} := CalibValue("rob1_" + NumToStr(i, 0));
        ENDFOR
        IF CalibValue("track1") <> NOT_CONFIGURED THEN
            TPWrite "Robot on a track";
        ENDIF
    ENDPROC

    LOCAL FUNC num CalibValue(string arm)
        VAR num value;
        ReadCfgData "/MOC/ARM/" + arm, "cal_position", value;
        RETURN value;
    ERROR
        IF ERRNO = ERR_CFG_NOTFND THEN
            missing := missing + 1;
            SkipWarn;
            RETURN NOT_CONFIGURED;
        ENDIF
    ENDFUNC
ENDMODULE
