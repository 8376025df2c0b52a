MODULE PlcRecord
    ! A record PERS a PC writes: each value component takes its own domain, and the verdict
    ! names the record itself (not some other num).
    RECORD plccmd
        bool go;
        num code;
        string part;
    ENDRECORD
    PERS plccmd cmdFromPlc := [FALSE, 0, ""];
    VAR num nCount := 0;

    PROC main()
        WaitUntil cmdFromPlc.go;
        IF cmdFromPlc.code = 3 AND cmdFromPlc.part = "A" THEN
            nCount := nCount + 1;
        ENDIF
    ENDPROC
ENDMODULE
