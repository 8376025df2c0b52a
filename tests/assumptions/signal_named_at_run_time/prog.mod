MODULE SignalNamedAtRunTime
    ! No EIO.cfg is loaded, so which signals the controller configures is not known: the
    ! names GetDataVal computes connect to a stand-in signal per call (an input read as a
    ! free one, an output read as one set outside the loaded code), not to ERR_SYM_ACCESS.
    VAR signaldo doStrobe;
    VAR signaldi diReady;
    VAR num nCnv := 0;

    PROC main()
        TPReadFK nCnv, "Conveyor", "CNV1", "CNV2", "", "", "";
        GetDataVal "c" + ValToStr(nCnv) + "NewObjStrobe", doStrobe;
        GetDataVal "c" + ValToStr(nCnv) + "Ready", diReady;
        WaitDI diReady, 1;
        ! the conveyor board sets the strobe: the wait ends
        WaitDO doStrobe, 1;
    ENDPROC
ENDMODULE
