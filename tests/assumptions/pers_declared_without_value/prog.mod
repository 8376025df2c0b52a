MODULE TargetsFromPc
    ! Issue 28: a PC writes the weld targets and the part's slot (Robot Web Services); the
    ! module declares them without a value and no RAPID code writes them. Their zeros are
    ! no value the PC gave: read as written data, the slot indexes the table, the divisor is
    ! not 0 and the rotation is a rotation. The verdicts say what the check assumed.
    PERS robtarget pWeld;
    PERS num nSlot;
    VAR num nSpeeds{3} := [100, 200, 300];
    VAR num nSpeed := 0;
    VAR num nAngle := 0;

    PROC main()
        nSpeed := nSpeeds{nSlot} / nSlot;
        nAngle := EulerZYX(\Z, pWeld.rot);
    ENDPROC
ENDMODULE
