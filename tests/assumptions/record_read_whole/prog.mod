MODULE PlcRecordWhole
    ! A record a PC writes, read by component in one place and whole in another: the whole
    ! read takes the same values as its components (before, it kept its initial value, so
    ! the division by zero below, with code 2, went unseen).
    RECORD plccmd
        bool go;
        num code;
    ENDRECORD
    PERS plccmd cmdFromPlc := [FALSE, 0];
    VAR num nCount := 0;
    VAR num nShare := 0;

    PROC main()
        VAR plccmd cmd;
        IF cmdFromPlc.code = 2 THEN
            nCount := nCount + 1;
        ENDIF
        cmd := cmdFromPlc;
        nShare := 10 / (cmd.code - 2);
    ENDPROC
ENDMODULE
