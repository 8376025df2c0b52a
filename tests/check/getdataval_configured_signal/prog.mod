MODULE GetDataValConfigured
    ! ABB's conveyor-tracking modules connect signal data to the signals of the conveyor the
    ! operator picks, by name: GetDataVal finds configured I/O signals as AliasIO does.
    ! EIO.cfg configures the signals of conveyors 1 and 2, the two keys offered.
    VAR signaldo doDrop;
    VAR signaldi diReady;
    VAR num nCnv := 0;

    PROC main()
        TPReadFK nCnv, "Conveyor", "CNV1", "CNV2", "", "", "";
        GetDataVal "c" + ValToStr(nCnv) + "DropWObj", doDrop;
        GetDataVal "c" + ValToStr(nCnv) + "Ready", diReady;
        WaitDI diReady, 1;
        PulseDO doDrop;
    ENDPROC
ENDMODULE
